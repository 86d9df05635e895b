// Meshes as the world has them, through the command line (issue 48): a closed mesh wound
// clockwise is turned and says so; an open sheet seen from behind says so, and two-sided
// faces light it; a file whose triangles have no area is refused with the reason; a flat
// mesh seen edge-on says why nothing is drawn; and the files of Debian's Assimp corpus that
// gave an empty frame without a word either draw or say why.
#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

struct Run
{
    int code = -1;
    QString err;
};

Run run(const QStringList &args)
{
    QProcess p;
    p.start(LIGHTBENCH_EXE, args);
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return {-1, "timed out"};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2,
            QString::fromUtf8(p.readAllStandardError())};
}

// Pixels that differ from the background (the top left pixel) by more than 2/255.
int drawnPixels(const QImage &image)
{
    const QRgb bg = image.pixel(0, 0);
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            n += std::abs(qRed(p) - qRed(bg)) > 2 || std::abs(qGreen(p) - qGreen(bg)) > 2 ||
                 std::abs(qBlue(p) - qBlue(bg)) > 2;
        }
    return n;
}

// Above the middle: the octahedron's upper faces, the sheet.
int brightness(const QImage &image)
{
    const QRgb p = image.pixel(image.width() / 2, image.height() / 2 - 12);
    return qRed(p) + qGreen(p) + qBlue(p);
}

} // namespace

class TestMeshesAsFound : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &text)
    {
        QFile f(m_dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
            qFatal("cannot write %s", qPrintable(f.fileName()));
        return f.fileName();
    }
    // Renders `mesh` at 160x120 head-on, without the light's marker; the frame's path.
    Run render(const QString &mesh, const QStringList &more, const QString &png)
    {
        return run(QStringList{"--mesh", mesh, "--render", m_dir.filePath(png), "--size", "160x120",
                               "--show-light", "off", "--camera-orbit", "0,0"} +
                   more);
    }

private slots:
    // An octahedron of our own, every face wound clockwise seen from outside.
    void clockwiseClosedMeshIsTurned()
    {
        const QString path =
            write("clockwise.obj", "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                   "f 1 5 3\nf 3 5 2\nf 2 5 4\nf 4 5 1\n"
                                   "f 1 3 6\nf 3 2 6\nf 2 4 6\nf 4 1 6\n");
        const Run turned = render(path, {}, "turned.png");
        QCOMPARE(turned.code, 0);
        QVERIFY2(turned.err.contains("clockwise.obj: faces turned: the file winds them clockwise"),
                 qPrintable(turned.err));
        const Run asIs = render(path, {"--faces", "file"}, "as_is.png");
        QCOMPARE(asIs.code, 0);
        QVERIFY2(!asIs.err.contains("turned"), qPrintable(asIs.err));
        const int lit = brightness(QImage(m_dir.filePath("turned.png")));
        const int inside = brightness(QImage(m_dir.filePath("as_is.png")));
        QVERIFY2(lit > inside + 60, qPrintable(QString("%1 against %2").arg(lit).arg(inside)));
    }

    // A square facing away from the camera: seen from behind, and lit with two-sided faces.
    void sheetSeenFromBehind()
    {
        const QString path =
            write("back.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 3 2\nf 1 4 3\n");
        const Run back = render(path, {}, "back.png");
        QCOMPARE(back.code, 0);
        QVERIFY2(back.err.contains("back.obj is seen from behind"), qPrintable(back.err));
        const Run both = render(path, {"--faces", "two-sided"}, "both.png");
        QCOMPARE(both.code, 0);
        QVERIFY2(both.err.isEmpty(), qPrintable(both.err));
        QVERIFY(brightness(QImage(m_dir.filePath("both.png"))) >
                brightness(QImage(m_dir.filePath("back.png"))) + 60);
    }

    void nothingToDraw_data()
    {
        QTest::addColumn<QByteArray>("obj");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("says");
        QTest::newRow("on a line") << QByteArray("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n") << 1
                                   << "triangle has no area (its corners lie on a line)";
        QTest::newRow("one point")
            << QByteArray("v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\nf 3 2 1\n") << 1
            << "2 triangles have no area (every vertex is at the same point)";
        QTest::newRow("edge-on")
            << QByteArray("v 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nf 1 2 3\nf 1 3 4\n") << 0
            << "draws nothing in view: it is flat (in the YZ plane) and seen edge-on";
        QTest::newRow("points only")
            << QByteArray("v 0 0 0\nv 1 0 0\np 1\np 2\n") << 1 << "no triangles";
    }
    void nothingToDraw()
    {
        QFETCH(QByteArray, obj);
        QFETCH(int, code);
        QFETCH(QString, says);
        const Run r = render(write("nothing.obj", obj), {}, "nothing.png");
        QCOMPARE(r.code, code);
        QVERIFY2(r.err.contains(says), qPrintable(r.err));
    }

    // The files that drew an empty frame without a word before (issue 48's list, 488 tried):
    // each now draws something, or says why on stderr.
    void corpusFilesDrawOrSayWhy_data()
    {
        QTest::addColumn<QString>("file");
        for (const char *f :
             {"AMF/test8.amf", "AMF/test9.amf", "ASE/ThreeCubesGreen_UTF16LE.ASE",
              "ASE/ThreeCubesGreen_UTF16BE.ASE", "BLEND/yxa_1.blend", "BVH/01_01.bvh",
              "BVH/Boxing_Toes.bvh", "BVH/01_03.bvh", "Collada/ConcavePolygon.dae",
              "Collada/anims_with_full_rotations_between_keys.DAE", "Collada/cameras.dae",
              "FBX/animation_with_skeleton.fbx", "LWO/LWO2/concave_polygon.lwo",
              "LWO/LWO2/concave_self_intersecting.lwo", "OBJ/concave_polygon.obj",
              "OBJ/number_formats.obj", "OBJ/regr_3429812.obj", "OBJ/space_in_material_name.obj",
              "OFF/invalid.off"})
            QTest::newRow(f) << QString("/usr/share/assimp/models/") + f;
    }
    void corpusFilesDrawOrSayWhy()
    {
        QFETCH(QString, file);
        if (!QFile::exists(file))
            QSKIP("Debian's assimp-testmodels is not installed");
        const QString png = m_dir.filePath("corpus.png");
        QFile::remove(png);
        const Run r =
            run({"--mesh", file, "--render", png, "--size", "160x120", "--show-light", "off"});
        QVERIFY2(r.code == 0 || r.code == 1, qPrintable(r.err));
        if (r.code == 1) {
            QVERIFY2(r.err.startsWith("lightbench: ") && r.err.size() > 20, qPrintable(r.err));
            return;
        }
        const int drawn = drawnPixels(QImage(png));
        QVERIFY2(drawn > 0 || !r.err.isEmpty(), "an empty frame and no word");
        qInfo("%d pixels drawn; %s", drawn, qPrintable(r.err.trimmed()));
    }

    void initTestCase() { QVERIFY(m_dir.isValid()); }
};

QTEST_GUILESS_MAIN(TestMeshesAsFound)
#include "test_meshes_as_found.moc"
