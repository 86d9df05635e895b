// The import helper's own PLY and binary STL readers (render/import/fast_mesh_readers.h) against
// Assimp's on the same files, both through the path the window uses (ImportProcess and the
// helper; LIGHTBENCH_IMPORT_READER=assimp makes the helper skip its own readers): the same
// vertices, normals, colours, indices, skipped faces and material for every file the fast
// readers read; files they decline (quads, texture coordinates, a texture file, other elements,
// a point cloud, ASCII STL) read by Assimp; files cut short refused with what is missing.
#include "import_process.h"

#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cstring>
#include <optional>

using namespace lb;

namespace {

// A PLY property: a list when `countType` is set.
struct Prop
{
    QByteArray type, name, countType = {};
};

enum class Format { Ascii, Little, Big };

void encode(QByteArray &out, const QByteArray &type, double v, Format f)
{
    if (f == Format::Ascii) {
        if (!out.isEmpty() && !out.endsWith('\n'))
            out += ' ';
        out += type.startsWith("float") || type.startsWith("double")
                   ? QByteArray::number(v, 'g', 17)
                   : QByteArray::number(qint64(v));
        return;
    }
    unsigned char b[8];
    std::size_t n = 0;
    auto put = [&](auto x) {
        n = sizeof x;
        std::memcpy(b, &x, n);
    };
    if (type == "char" || type == "int8")
        put(std::int8_t(v));
    else if (type == "uchar" || type == "uint8")
        put(std::uint8_t(v));
    else if (type == "short")
        put(std::int16_t(v));
    else if (type == "ushort")
        put(std::uint16_t(v));
    else if (type == "int" || type == "int32")
        put(std::int32_t(v));
    else if (type == "uint" || type == "uint32")
        put(std::uint32_t(v));
    else if (type == "float" || type == "float32")
        put(float(v));
    else
        put(double(v));
    if (f == Format::Big)
        std::reverse(b, b + n);
    out.append(reinterpret_cast<const char *>(b), qsizetype(n));
}

// Rows of values in property order; a list's row entry is its count, then its values.
QByteArray rows(const QList<Prop> &props, const QList<QList<double>> &data, Format f)
{
    QByteArray out;
    for (const QList<double> &row : data) {
        QByteArray line;
        qsizetype i = 0;
        for (const Prop &p : props) {
            if (p.countType.isEmpty()) {
                encode(line, p.type, row.value(i++), f);
                continue;
            }
            const int n = int(row.value(i++));
            encode(line, p.countType, n, f);
            for (int k = 0; k < n; ++k)
                encode(line, p.type, row.value(i++), f);
        }
        out += line;
        if (f == Format::Ascii)
            out += '\n';
    }
    return out;
}

QByteArray header(const QList<Prop> &props)
{
    QByteArray h;
    for (const Prop &p : props)
        h += p.countType.isEmpty()
                 ? "property " + p.type + " " + p.name + "\n"
                 : "property list " + p.countType + " " + p.type + " " + p.name + "\n";
    return h;
}

QByteArray ply(Format f, const QList<Prop> &vprops, const QList<QList<double>> &vertices,
               const QList<Prop> &fprops, const QList<QList<double>> &faces,
               const QByteArray &extraHeader = {})
{
    const char *format = f == Format::Ascii    ? "ascii"
                         : f == Format::Little ? "binary_little_endian"
                                               : "binary_big_endian";
    QByteArray h = QByteArray("ply\nformat ") + format +
                   " 1.0\ncomment made by lightbench's test\n" + extraHeader + "element vertex " +
                   QByteArray::number(vertices.size()) + "\n" + header(vprops);
    if (!fprops.isEmpty())
        h += "element face " + QByteArray::number(faces.size()) + "\n" + header(fprops);
    h += "end_header\n";
    return h + rows(vprops, vertices, f) +
           (fprops.isEmpty() ? QByteArray() : rows(fprops, faces, f));
}

const QList<Prop> kXyz = {{"float", "x"}, {"float", "y"}, {"float", "z"}};
const QList<Prop> kCorners = {{"int", "vertex_indices", "uchar"}};
// A square of two triangles and one more apart, in 3D.
const QList<QList<double>> kFour = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}};
const QList<QList<double>> kTwoTriangles = {{3, 0, 1, 2}, {3, 0, 2, 3}};

// kFour with more values on each vertex.
QList<QList<double>> withValues(const QList<QList<double>> &more)
{
    QList<QList<double>> out = kFour;
    for (qsizetype i = 0; i < out.size(); ++i)
        out[i].append(more[i % more.size()]);
    return out;
}

// A binary STL of `facets` (normal, three corners, attribute), after an 80-byte header.
QByteArray stl(const QByteArray &headerText, const QList<QList<float>> &facets,
               const QList<std::uint16_t> &attributes)
{
    QByteArray b = headerText.leftJustified(80, ' ', true);
    const std::uint32_t n = std::uint32_t(facets.size());
    b.append(reinterpret_cast<const char *>(&n), 4);
    for (qsizetype f = 0; f < facets.size(); ++f) {
        for (float v : facets[f])
            b.append(reinterpret_cast<const char *>(&v), 4);
        const std::uint16_t a = attributes.value(f);
        b.append(reinterpret_cast<const char *>(&a), 2);
    }
    return b;
}

const QList<QList<float>> kFacets = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0},
                                     {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0},
                                     {0, -1, 0, 0, 0, 0, 0, 0, 1, 1, 0, 0}};

ImportResult importWith(const QString &path, bool assimpOnly)
{
    if (assimpOnly)
        qputenv("LIGHTBENCH_IMPORT_READER", "assimp");
    else
        qunsetenv("LIGHTBENCH_IMPORT_READER");
    ImportLimits limits;
    limits.seconds = 60;
    ImportResult r = ImportProcess::import(path, limits);
    qunsetenv("LIGHTBENCH_IMPORT_READER");
    return r;
}

template <typename V> bool nearArrays(const std::vector<V> &a, const std::vector<V> &b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < V::length(); ++c)
            if (std::abs(a[i][c] - b[i][c]) > 1e-6f)
                return false;
    return true;
}

bool same(const std::optional<glm::vec3> &a, const std::optional<glm::vec3> &b)
{
    return a.has_value() == b.has_value() && (!a || glm::all(glm::equal(*a, *b)));
}

} // namespace

class TestFastReaders : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    int m_short = 0;

    QString file(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

private slots:
    void initTestCase() { QVERIFY2(m_dir.isValid(), "no temporary directory"); }

    void sameAsAssimp_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("reader");
        using F = Format;
        const QList<Prop> doubles = {{"double", "x"}, {"double", "y"}, {"double", "z"}};
        const QList<Prop> normals = {{"float", "nx"}, {"float", "ny"}, {"float", "nz"}};
        const QList<Prop> uchars = {{"uchar", "red"}, {"uchar", "green"}, {"uchar", "blue"}};
        // Corners out of range and a face of two corners: skipped on both routes.
        const QList<QList<double>> oddFaces = {{3, 0, 1, 2}, {3, 0, 2, 9}, {2, 0, 1}, {3, 0, 2, 3}};
        QTest::newRow("ascii: doubles, normals, uchar colours, a bad index, a 2-corner face")
            << "a.ply"
            << ply(F::Ascii, doubles + normals + uchars,
                   {{0, 0, 0.1, 0, 0, 1, 255, 0, 10},
                    {1.25, 0, 0, 0, 0.6, 0.8, 0, 128, 20},
                    {1, 1, 0.5, 0, 0, 1, 7, 7, 7},
                    {-0.333333333333, 1, 0, 1, 0, 0, 1, 2, 3}},
                   kCorners, oddFaces)
            << "ply";
        QTest::newRow("little-endian: an extra vertex property, rgba")
            << "le.ply"
            << ply(F::Little,
                   kXyz + QList<Prop>{{"float", "confidence"}} + uchars +
                       QList<Prop>{{"uchar", "alpha"}},
                   withValues({{0.5, 10, 20, 30, 40}, {0.25, 250, 0, 1, 255}}), kCorners,
                   kTwoTriangles)
            << "ply";
        QTest::newRow("big-endian: doubles, ushort colours, uint corners, a face flag")
            << "be.ply"
            << ply(F::Big, doubles + QList<Prop>{{"ushort", "r"}, {"ushort", "g"}, {"ushort", "b"}},
                   withValues({{65535, 1000, 0}, {3, 30000, 65000}}),
                   {{"uint", "vertex_index", "uchar"}, {"uchar", "flags"}},
                   {{3, 0, 1, 2, 7}, {3, 0, 2, 3, 9}})
            << "ply";
        QTest::newRow("ascii: char, short and int colours, CRLF lines")
            << "crlf.ply"
            << ply(F::Ascii,
                   kXyz + QList<Prop>{{"char", "red"}, {"short", "green"}, {"int", "blue"}},
                   withValues({{-100, -30000, 12}, {120, 30000, -40}}), kCorners, kTwoTriangles)
                   .replace("\n", "\r\n")
            << "ply";
        QTest::newRow("little-endian: alpha alone, nx alone, uint and double colours")
            << "alpha.ply"
            << ply(F::Little,
                   kXyz + QList<Prop>{{"float", "nx"},
                                      {"uint", "red"},
                                      {"double", "blue"},
                                      {"uchar", "alpha"}},
                   withValues({{1, 70000, 0.25, 128}, {-1, 5, 0.75, 255}}), kCorners, kTwoTriangles)
            << "ply";
        QTest::newRow("big-endian: int8 coordinates, negative and large corners")
            << "int8.ply"
            << ply(F::Big, {{"char", "x"}, {"char", "y"}, {"char", "z"}},
                   {{0, 0, 0}, {100, 0, 0}, {100, 100, 50}, {-3, 100, 0}},
                   {{"int", "vertex_indices", "int"}},
                   {{3, 0, 1, 2}, {3, 0, -1, 2}, {3, 0, 2, 3}, {1, 2}})
            << "ply";
        // Declined: read by Assimp, as before the fast readers.
        QTest::newRow("quads: Assimp triangulates them")
            << "quads.ply" << ply(F::Little, kXyz, kFour, kCorners, {{4, 0, 1, 2, 3}}) << "assimp";
        QTest::newRow("texture coordinates")
            << "uv.ply"
            << ply(F::Ascii, kXyz + QList<Prop>{{"float", "u"}, {"float", "v"}},
                   withValues({{0, 0}, {1, 1}}), kCorners, kTwoTriangles)
            << "assimp";
        QTest::newRow("a texture file in a comment")
            << "texture.ply"
            << ply(F::Ascii, kXyz, kFour, kCorners, kTwoTriangles, "comment TextureFile none.png\n")
            << "assimp";
        QTest::newRow("a list in the vertex element")
            << "vlist.ply"
            << ply(F::Ascii, kXyz + QList<Prop>{{"int", "ring", "uchar"}}, withValues({{1, 5}}),
                   kCorners, kTwoTriangles)
            << "assimp";
        const QByteArray plain = stl("binary STL from the test", kFacets, {});
        QTest::newRow("binary STL") << "plain.stl" << plain << "stl";
        QTest::newRow("binary STL whose header starts with solid")
            << "solid.stl" << stl("solid cube", kFacets, {}) << "stl";
        QTest::newRow("binary STL with coloured facets")
            << "coloured.stl" << stl("VisCAM colours", kFacets, {0, 0x8000 | 0x7c00, 0x801f})
            << "stl";
        QTest::newRow("Materialise STL: COLOR= and coloured facets")
            << "materialise.stl"
            << stl(QByteArray("COLOR=") + "\x20\x40\x80\xff" + " MATERIAL=", kFacets,
                   {0x8000 | 0x001f, 0, 0x8000 | (12 << 5)})
            << "stl";
        QTest::newRow("Materialise STL: COLOR= alone gives the material")
            << "header-colour.stl" << stl(QByteArray("xCOLOR=") + "\x10\x20\x30\xff", kFacets, {})
            << "stl";
        QTest::newRow("ASCII STL")
            << "ascii.stl"
            << QByteArray("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                          "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n")
            << "assimp";
    }

    // Both routes give the same mesh, the material and counts; the default route's reader
    // is the one expected.
    void sameAsAssimp()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(QString, reader);
        const QString path = file(name, bytes);
        const ImportResult fast = importWith(path, false), assimp = importWith(path, true);
        QVERIFY2(fast.ok(), qPrintable(fast.error));
        QVERIFY2(assimp.ok(), qPrintable(assimp.error));
        QCOMPARE(fast.file->reader, reader);
        QCOMPARE(assimp.file->reader, QString("assimp"));
        const Mesh &a = *fast.file->mesh, &b = *assimp.file->mesh;
        QCOMPARE(a.vertexCount(), b.vertexCount());
        QVERIFY(a.triangleCount() > 0);
        QVERIFY(nearArrays(a.positions, b.positions));
        QVERIFY(nearArrays(a.normals, b.normals));
        QVERIFY(nearArrays(a.colors, b.colors));
        QVERIFY(a.indices == b.indices);
        QCOMPARE(a.uvs.size(), b.uvs.size());
        QCOMPARE(fast.file->skippedFaces, assimp.file->skippedFaces);
        QCOMPARE(fast.file->meshes, assimp.file->meshes);
        const FileMaterial &m = fast.file->material, &n = assimp.file->material;
        QVERIFY(same(m.ka, n.ka) && same(m.kd, n.kd) && same(m.ks, n.ks));
        QCOMPARE(m.shininess.has_value(), n.shininess.has_value());
        qInfo("%s: %zu vertices, %zu triangles, %lld skipped, read by %s", qPrintable(name),
              a.vertexCount(), a.triangleCount(), fast.file->skippedFaces, qPrintable(reader));
    }

    // Files cut short, or whose counts promise more than they hold: refused with what is
    // missing, in bounded time, never read by Assimp.
    void shortFilesRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("said");
        const QByteArray full = ply(Format::Little, kXyz, kFour, kCorners, kTwoTriangles);
        QTest::newRow("binary cut in its faces")
            << full.left(full.size() - 5) << "the file ends before its 2 faces (1 read)";
        QTest::newRow("binary cut in its vertices")
            << full.left(full.indexOf("end_header\n") + 11 + 20)
            << "the file ends before its 4 vertices and 2 faces";
        QByteArray huge = full;
        huge.replace("element face 2", "element face 1000000000");
        QTest::newRow("binary: 1e9 faces in a tiny file") << huge << "1000000000 faces";
        const QByteArray ascii = ply(Format::Ascii, kXyz, kFour, kCorners, kTwoTriangles);
        QTest::newRow("ascii cut in its faces")
            << ascii.left(ascii.lastIndexOf("3 0 2 3")) << "the file ends before its 2 faces";
        QTest::newRow("binary STL cut") << stl("cut", kFacets, {}).chopped(10) << "";
    }

    void shortFilesRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, said);
        const QString path =
            file(QString("short-%1%2").arg(++m_short).arg(said.isEmpty() ? ".stl" : ".ply"), bytes);
        const ImportResult r = importWith(path, false);
        if (said.isEmpty()) { // an STL of the wrong size is not binary: Assimp's to refuse
            QVERIFY(!r.ok());
            return;
        }
        QVERIFY2(!r.ok(), "a short file loaded");
        QVERIFY2(r.error.contains(said), qPrintable(r.error));
    }

    // A face of no corners aborts Assimp's reader (an assertion); the fast reader skips it.
    void faceOfNoCorners()
    {
        const QString path = file("empty-face.ply", ply(Format::Little, kXyz, kFour, kCorners,
                                                        {{3, 0, 1, 2}, {0}, {3, 0, 2, 3}}));
        const ImportResult r = importWith(path, false);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.file->reader, QString("ply"));
        QCOMPARE(r.file->mesh->triangleCount(), std::size_t(2));
        QCOMPARE(r.file->skippedFaces, 1);
    }

    // Debian's corpus: every PLY and STL gives on the default route what Assimp alone gives
    // (the same mesh, or the same refusal), whichever reader took it.
    void corpusAsAssimpGivesIt()
    {
        const QString corpus = "/usr/share/assimp/models";
        if (!QFileInfo(corpus).isDir())
            QSKIP("the assimp-testmodels package is missing (scripts/setup.sh installs it)");
        QDirIterator it(corpus, {"*.ply", "*.PLY", "*.stl", "*.STL"}, QDir::Files,
                        QDirIterator::Subdirectories);
        int files = 0, fastOnes = 0;
        while (it.hasNext()) {
            const QString path = it.next();
            ++files;
            const ImportResult fast = importWith(path, false), assimp = importWith(path, true);
            QVERIFY2(fast.ok() == assimp.ok(), qPrintable(path + ": " + fast.error + assimp.error));
            if (!fast.ok()) {
                QCOMPARE(fast.error, assimp.error);
                continue;
            }
            fastOnes += fast.file->reader != "assimp";
            const Mesh &a = *fast.file->mesh, &b = *assimp.file->mesh;
            QVERIFY2(nearArrays(a.positions, b.positions) && nearArrays(a.normals, b.normals) &&
                         nearArrays(a.colors, b.colors) && a.indices == b.indices &&
                         a.uvs.size() == b.uvs.size(),
                     qPrintable(path));
        }
        qInfo("corpus: %d PLY and STL files, %d read by the fast readers", files, fastOnes);
        QVERIFY(files > 10);
        QVERIFY(fastOnes >= 4); // cube_binary.ply, float-color.ply, three binary STLs
    }

    // A point cloud (no face element) is Assimp's, and refused as it was: no triangles.
    void pointCloud()
    {
        const QString path = file("cloud.ply", ply(Format::Little, kXyz, kFour, {}, {}));
        const ImportResult fast = importWith(path, false), assimp = importWith(path, true);
        QVERIFY(!fast.ok() && !assimp.ok());
        QCOMPARE(fast.error, assimp.error);
    }
};

QTEST_GUILESS_MAIN(TestFastReaders)
#include "test_fast_readers.moc"
