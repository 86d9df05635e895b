// Files a mesh refers to (an OBJ's material library, a glTF's buffers) get the checks the mesh
// file gets, inside the import helper: a FIFO named as a material library hung the import for
// its whole time limit, a 4 GB sparse one made the helper read 4 GB, a glTF buffer named
// "../../../../../etc/passwd" was read and drawn. And non-finite coordinates (NaN, inf) in a
// mesh are dropped with the triangles using them, and said so. Every bad input is made here,
// in a temporary folder, through the path the window uses (ImportProcess and the helper).
#include "import_process.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

using namespace lb;

namespace {

// Each hostile file must end well within this, with its message.
constexpr qint64 kQuickMs = 20000;

void write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY2(f.open(QIODevice::WriteOnly), qPrintable(path));
    f.write(bytes);
}

void makeFifo(const QString &path)
{
    QVERIFY2(mkfifo(QFile::encodeName(path).constData(), 0600) == 0, qPrintable(path));
}

void makeSparse(const QString &path, qint64 bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.resize(bytes)); // a hole: no disk used
}

// A triangle with a material; its material library is `library`.
QByteArray objNaming(const QString &library)
{
    return "mtllib " + library.toUtf8() + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n";
}

const QByteArray kLibrary = "newmtl paint\nKd 0.2 0.4 0.6\nNs 50\n";

// A glTF 2.0 triangle whose positions and indices are in the buffer `uri` (44 bytes: nine
// floats, three 16-bit indices, two bytes of padding), with a base colour.
QByteArray gltfNaming(const QString &uri)
{
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}],
  "buffers": [{"uri": ")" +
           uri.toUtf8() + R"(", "byteLength": 44}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

QByteArray triangleBuffer()
{
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[4] = {0, 1, 2, 0};
    QByteArray b(reinterpret_cast<const char *>(positions), sizeof positions);
    b.append(reinterpret_cast<const char *>(indices), sizeof indices);
    return b;
}

struct Timed
{
    ImportResult result;
    qint64 ms = 0;
    QString said; // the error, or the remarks of a mesh that loaded
};

Timed importTimed(const QString &path, qint64 memoryMB = 0)
{
    ImportLimits limits;
    if (memoryMB > 0)
        limits.memoryMB = memoryMB;
    limits.seconds = 60; // the test's own bound; what matters is kQuickMs
    QElapsedTimer clock;
    clock.start();
    Timed t;
    t.result = ImportProcess::import(path, limits);
    t.ms = clock.elapsed();
    t.said = t.result.ok() ? t.result.file->remarks().join("; ") : t.result.error;
    qInfo("%s: %s in %lld ms (helper peak %lld KB): %s", qPrintable(QFileInfo(path).fileName()),
          t.result.ok() ? "loaded" : "refused", t.ms,
          t.result.ok() ? t.result.file->helperPeakKB : -1ll, qPrintable(t.said));
    return t;
}

bool near(const glm::vec3 &a, const glm::vec3 &b)
{
    return glm::length(a - b) < 1e-5f;
}

} // namespace

class TestSideFiles : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    QString folder(const QString &name)
    {
        const QString path = m_dir.filePath(name);
        QDir().mkpath(path);
        return path;
    }

private slots:
    void initTestCase() { QVERIFY2(m_dir.isValid(), "no temporary directory"); }

    // The good cases first: what the checks must let through.
    void objWithItsMaterialLibraryLoads()
    {
        const QString dir = folder("good-obj");
        write(dir + "/materials.mtl", kLibrary);
        write(dir + "/quad.obj", objNaming("materials.mtl"));
        const Timed t = importTimed(dir + "/quad.obj");
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        QVERIFY2(t.result.file->sideFileProblems.isEmpty(), qPrintable(t.said));
        QVERIFY(t.result.file->material.kd &&
                near(*t.result.file->material.kd, glm::vec3(0.2f, 0.4f, 0.6f)));
        QCOMPARE(t.result.file->material.shininess.value_or(0.0f), 50.0f);
    }

    void gltfWithItsBufferLoads()
    {
        // The buffer in a folder below the mesh's: "and below" is inside.
        const QString dir = folder("good-gltf");
        folder("good-gltf/buffers");
        write(dir + "/buffers/tri.bin", triangleBuffer());
        write(dir + "/tri.gltf", gltfNaming("buffers/tri.bin"));
        const Timed t = importTimed(dir + "/tri.gltf");
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        QCOMPARE(t.result.file->mesh->triangleCount(), std::size_t(1));
        QVERIFY2(t.result.file->sideFileProblems.isEmpty(), qPrintable(t.said));
        QVERIFY(t.result.file->material.kd &&
                near(*t.result.file->material.kd, glm::vec3(0.2f, 0.4f, 0.6f)));
    }

    // A material library Assimp can do without: the mesh loads with the default material,
    // and the remark names the file and why it was not read.
    void refusedMaterialLibraryLoadsWithoutIt_data()
    {
        QTest::addColumn<QString>("make"); // what materials.mtl is
        QTest::addColumn<QString>("expected");
        QTest::newRow("FIFO") << "fifo"
                              << "materials.mtl: not a regular file (a FIFO)";
        QTest::newRow("sparse 4 GB")
            << "sparse"
            << "materials.mtl: 4096 MB is more than a material library may be (64 MB)";
        QTest::newRow("folder") << "folder"
                                << "materials.mtl: not a regular file (a folder)";
        QTest::newRow("device") << "device"
                                << "materials.mtl: not a regular file (a device)";
        QTest::newRow("outside") << "outside"
                                 << "materials.mtl: outside the mesh's folder";
        QTest::newRow("missing") << "missing"
                                 << "materials.mtl: no such file";
    }

    void refusedMaterialLibraryLoadsWithoutIt()
    {
        QFETCH(QString, make);
        QFETCH(QString, expected);
        const QString dir = folder("mtl-" + make);
        const QString library = dir + "/materials.mtl";
        if (make == "fifo")
            makeFifo(library);
        else if (make == "sparse")
            makeSparse(library, 4ll << 30);
        else if (make == "folder")
            QVERIFY(QDir().mkpath(library));
        else if (make == "device") // a link to /dev/zero: links are resolved before the check
            QVERIFY(QFile::link("/dev/zero", library));
        else if (make == "outside") { // a good library, but through a link out of the folder
            write(m_dir.filePath("elsewhere.mtl"), kLibrary);
            QVERIFY(QFile::link(m_dir.filePath("elsewhere.mtl"), library));
        }
        write(dir + "/quad.obj", objNaming("materials.mtl"));

        const Timed t = importTimed(dir + "/quad.obj");
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        QCOMPARE(t.result.file->sideFileProblems, QStringList{expected}); // said once, alone
        // Not read: the default material (Assimp's, for the name "paint").
        QVERIFY(t.result.file->material.kd &&
                !near(*t.result.file->material.kd, glm::vec3(0.2f, 0.4f, 0.6f)));
        QVERIFY2(t.ms < kQuickMs, qPrintable(QString::number(t.ms)));
        QVERIFY2(t.result.file->helperPeakKB < 2 * 1024 * 1024,
                 qPrintable(QString::number(t.result.file->helperPeakKB)));
    }

    // A buffer Assimp cannot do without: the mesh is refused, with the file and why.
    void refusedGltfBufferRefusesTheMesh_data()
    {
        QTest::addColumn<QString>("make");
        QTest::addColumn<QString>("uri");
        QTest::addColumn<QString>("expected");
        QTest::newRow("FIFO") << "fifo"
                              << "pipe.bin"
                              << "pipe.bin: not a regular file (a FIFO)";
        QTest::newRow("dot-dot to /etc/passwd") << ""
                                                << "../../../../../../../../etc/passwd"
                                                << "../../../../../../../../etc/passwd: outside "
                                                   "the mesh's folder";
        // glTF puts the mesh's folder before a name that starts with '/'.
        QTest::newRow("absolute /etc/passwd") << ""
                                              << "/etc/passwd"
                                              << "etc/passwd: no such file";
        QTest::newRow("link out") << "link"
                                  << "link.bin"
                                  << "link.bin: outside the mesh's folder";
        QTest::newRow("sparse 4 GB over a 1 GB limit")
            << "sparse"
            << "big.bin"
            << "big.bin: 4096 MB is more than a file a mesh refers to may be (1024 MB, the "
               "import memory limit)";
    }

    void refusedGltfBufferRefusesTheMesh()
    {
        QFETCH(QString, make);
        QFETCH(QString, uri);
        QFETCH(QString, expected);
        const QString dir = folder("gltf-" + QString(QTest::currentDataTag()).replace(' ', '-'));
        if (make == "fifo")
            makeFifo(dir + "/" + uri);
        else if (make == "sparse")
            makeSparse(dir + "/" + uri, 4ll << 30);
        else if (make == "link") { // a good buffer, outside the folder
            write(m_dir.filePath("outside.bin"), triangleBuffer());
            QVERIFY(QFile::link(m_dir.filePath("outside.bin"), dir + "/" + uri));
        }
        write(dir + "/scene.gltf", gltfNaming(uri));

        const Timed t = importTimed(dir + "/scene.gltf", 1024);
        QVERIFY2(!t.result.ok(), "loaded: a refused buffer was read after all");
        QVERIFY2(t.said.startsWith(dir + "/scene.gltf: " + expected), qPrintable(t.said));
        QVERIFY2(t.ms < kQuickMs, qPrintable(QString::number(t.ms)));
    }

    // The texture a material names is read by the workbench, under the same rule: a picture
    // from outside the mesh's folder is not shown; one beside the mesh is.
    void textureOutsideTheFolderIsNotShown_data()
    {
        QTest::addColumn<QString>("named"); // map_Kd; %1 is the temporary folder
        QTest::addColumn<QString>("expected");
        QTest::newRow("dot-dot") << "../secret.png"
                                 << "texture '../secret.png': outside the mesh's folder";
        QTest::newRow("absolute") << "%1/secret.png"
                                  << "texture '%1/secret.png': outside the mesh's folder";
        QTest::newRow("link out") << "link.png"
                                  << "texture 'link.png': outside the mesh's folder";
        QTest::newRow("beside") << "own.png"
                                << "";
    }

    void textureOutsideTheFolderIsNotShown()
    {
        QFETCH(QString, named);
        QFETCH(QString, expected);
        named.replace("%1", m_dir.path());
        expected.replace("%1", m_dir.path());
        QImage picture(4, 4, QImage::Format_RGB32);
        picture.fill(Qt::red);
        QVERIFY(picture.save(m_dir.filePath("secret.png")));
        const QString dir = folder("tex-" + QString(QTest::currentDataTag()).replace(' ', '-'));
        QVERIFY(picture.save(dir + "/own.png"));
        QFile::link(m_dir.filePath("secret.png"), dir + "/link.png");
        write(dir + "/materials.mtl", kLibrary + "map_Kd " + named.toUtf8() + "\n");
        write(dir + "/quad.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                                 "vt 1 0\nvt 0 1\nusemtl paint\nf 1/1 2/2 3/3\n");
        const Timed t = importTimed(dir + "/quad.obj");
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        QCOMPARE(t.result.file->textureProblem, expected);
        QCOMPARE(bool(t.result.file->texture), expected.isEmpty());
    }

    // NaN and +-inf positions: those vertices and the triangles using them are dropped, and
    // said; what is sent is finite and still fits the view.
    void nonFinitePositionsAreDropped_data()
    {
        QTest::addColumn<QByteArray>("bad"); // the fourth vertex
        QTest::newRow("nan") << QByteArray("v nan 0 0");
        QTest::newRow("inf") << QByteArray("v inf 1 2");
        QTest::newRow("-inf") << QByteArray("v 0 -inf 0");
        QTest::newRow("NaN in z") << QByteArray("v 0 0 NaN");
    }

    void nonFinitePositionsAreDropped()
    {
        QFETCH(QByteArray, bad);
        const QString path = m_dir.filePath("nonfinite.obj");
        write(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + bad + "\nf 1 2 3\nf 1 2 4\nf 4 3 2\n");
        const Timed t = importTimed(path);
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        const Mesh &mesh = *t.result.file->mesh;
        QCOMPARE(mesh.vertexCount(), std::size_t(3));
        QCOMPARE(mesh.triangleCount(), std::size_t(1));
        for (const glm::vec3 &p : mesh.positions)
            QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        // Assimp reads an OBJ without joining vertices: the bad one is there once per face.
        QVERIFY2(t.said.contains("2 vertices with non-finite coordinates dropped, with the 2 "
                                 "triangles using them"),
                 qPrintable(t.said));
    }

    void onlyNonFiniteTrianglesRefuseTheMesh()
    {
        const QString path = m_dir.filePath("allbad.obj");
        write(path, "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
        const Timed t = importTimed(path);
        QVERIFY(!t.result.ok());
        QVERIFY2(t.said.contains("no triangles with finite coordinates (1 vertices with "
                                 "non-finite coordinates)"),
                 qPrintable(t.said));
    }

    void nonFiniteNormalsAreNotUsed()
    {
        const QString path = m_dir.filePath("badnormal.obj");
        write(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn nan 0 1\n"
                    "f 1//1 2//1 3//2\n");
        const Timed t = importTimed(path);
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        QVERIFY(!t.result.file->hasNormals()); // the workbench generates them
        QVERIFY2(t.said.contains("1 normals with non-finite coordinates: the file's normals not "
                                 "used"),
                 qPrintable(t.said));
    }

    // Finite, but so far apart that their extent overflows a float: still fitted to the view
    // (the bounds are taken in double), not sent as they are.
    void hugeFiniteCoordinatesStillFit()
    {
        const QString path = m_dir.filePath("huge.obj");
        write(path, "v -3e38 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n");
        const Timed t = importTimed(path);
        QVERIFY2(t.result.ok(), qPrintable(t.said));
        for (const glm::vec3 &p : t.result.file->mesh->positions)
            QVERIFY2(std::abs(p.x) <= 1.0001f && std::abs(p.y) <= 1.0001f,
                     qPrintable(QString("%1 %2").arg(p.x).arg(p.y)));
    }
};

QTEST_GUILESS_MAIN(TestSideFiles)
#include "test_side_files.moc"
