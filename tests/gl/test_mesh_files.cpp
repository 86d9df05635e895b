// Mesh files drawn by the built-in shaders, pixel by pixel against the CPU reference: the
// file's own normals, generated smooth and flat ones, node transforms and the fit to the view,
// the file's diffuse texture; and the normal lines.
#include "import_process.h"
#include "reference_compare.h"

#include <QFile>
#include <QGuiApplication>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;
using namespace lb::test;

namespace {
const QString kCorpus = "/usr/share/assimp/models";
}

class TestMeshFiles : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;
    QTemporaryDir m_dir;

    Scene sceneWith(const QString &path)
    {
        const ImportResult r = ImportProcess::import(path);
        if (!r.ok())
            qFatal("%s", qPrintable(r.error));
        m_offscreen.addMeshFile(r.file);
        Scene s = testScene();
        s.objects[0].meshPath = r.file->path;
        return s;
    }

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(m_dir.isValid());
    }

    void filesMatchTheReference_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("normals");
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("minCompared");
        const std::pair<const char *, int> files[] = {
            {"PLY/cube.ply", 400},
            {"OBJ/WusonOBJ.obj", 25},
            {"glTF2/BoxTextured-glTF/BoxTextured.gltf", 400}};
        for (const auto &[file, minCompared] : files)
            for (int n = 0; n < 3; ++n)
                for (int sh = 0; sh < 2; ++sh)
                    QTest::newRow(qPrintable(
                        QString("%1 %2 %3").arg(file, toName(NormalMode(n)), toName(Shading(sh)))))
                        << QString(file) << n << sh << minCompared;
    }

    void filesMatchTheReference()
    {
        QFETCH(QString, file);
        QFETCH(int, normals);
        QFETCH(int, shading);
        QFETCH(int, minCompared);
        Scene s = sceneWith(kCorpus + "/" + file);
        s.objects[0].normals = NormalMode(normals);
        s.shading.shading = Shading(shading);
        s.lights[0].position = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
        s.objects[0].material.shininess = 10;
        const QString failure =
            checkAgainstReference(m_offscreen, s, QTest::currentDataTag(), minCompared, 0);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
    }

    void theFilesTextureMatchesTheReference()
    {
        // A quad in front of the camera with a 2x2 texture of four colours, bilinear between.
        QImage texture(2, 2, QImage::Format_RGB32);
        texture.setPixelColor(0, 0, QColor(250, 40, 40));
        texture.setPixelColor(1, 0, QColor(40, 250, 40));
        texture.setPixelColor(0, 1, QColor(40, 40, 250));
        texture.setPixelColor(1, 1, QColor(250, 250, 40));
        QVERIFY(texture.save(m_dir.filePath("four.png")));
        QFile mtl(m_dir.filePath("quad.mtl"));
        QVERIFY(mtl.open(QIODevice::WriteOnly));
        mtl.write("newmtl four\nKd 1 1 1\nmap_Kd four.png\n");
        mtl.close();
        QFile obj(m_dir.filePath("quad.obj"));
        QVERIFY(obj.open(QIODevice::WriteOnly));
        obj.write("mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl four\n"
                  "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
        obj.close();
        Scene s = sceneWith(m_dir.filePath("quad.obj"));
        s.objects[0].rotationDegrees = glm::vec3(0.0f);
        s.objects[0].scale = glm::vec3(1.0f);
        s.camera.yawDegrees = s.camera.pitchDegrees = 0.0f;
        s.objects[0].texture = true;
        const QString failure = checkAgainstReference(m_offscreen, s, "textured quad", 400, 0);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
        QCOMPARE(m_offscreen.renderer().texture().image().width(), 2); // the file's, no checker
        // Top left of the picture is the image's top left (t = 1 is the top row of the file).
        const QImage frame = m_offscreen.render(s);
        const QRgb topLeft = frame.pixel(kSize.width() / 2 - 60, kSize.height() / 2 - 60);
        QVERIFY2(qRed(topLeft) > qGreen(topLeft) && qRed(topLeft) > qBlue(topLeft),
                 qPrintable(QString::number(topLeft, 16)));
    }

    // A sphere of our own wound clockwise (as the Stanford bunny's bun_zipper.ply is), in an
    // OBJ without normals: each Faces choice drawn by the built-in shaders matches the CPU
    // reference (the probe's) on the same mesh, and the outward and two-sided ones are lit
    // from outside: brighter than the file's inside-out surface (issue 48).
    void insideOutFileMatchesTheReference_data()
    {
        QTest::addColumn<int>("faces");
        QTest::addColumn<int>("shading");
        QTest::addColumn<bool>("litOutside");
        for (int f = 0; f < 4; ++f)
            for (int sh = 0; sh < 2; ++sh)
                QTest::newRow(
                    qPrintable(QString("%1 %2").arg(toName(Faces(f)), toName(Shading(sh)))))
                    << f << sh << (Faces(f) != Faces::File);
    }
    void insideOutFileMatchesTheReference()
    {
        QFETCH(int, faces);
        QFETCH(int, shading);
        QFETCH(bool, litOutside);
        const QString path = m_dir.filePath("inside_out.obj");
        if (!QFile::exists(path)) {
            const Mesh sphere = makeSphere(32, 16);
            QByteArray text;
            for (const glm::vec3 &p : sphere.positions)
                text += QByteArray("v ") + QByteArray::number(p.x) + ' ' + QByteArray::number(p.y) +
                        ' ' + QByteArray::number(p.z) + '\n';
            for (std::size_t t = 0; t < sphere.triangleCount(); ++t) // clockwise: 1, 3, 2
                text += "f " + QByteArray::number(sphere.indices[3 * t] + 1) + ' ' +
                        QByteArray::number(sphere.indices[3 * t + 2] + 1) + ' ' +
                        QByteArray::number(sphere.indices[3 * t + 1] + 1) + '\n';
            QFile obj(path);
            QVERIFY(obj.open(QIODevice::WriteOnly));
            QCOMPARE(obj.write(text), qint64(text.size()));
        }
        Scene s = sceneWith(path);
        s.objects[0].faces = Faces(faces);
        s.shading.shading = Shading(shading);
        s.lights[0].position = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
        s.objects[0].material.shininess = 10;
        const QString failure = checkAgainstReference(m_offscreen, s, QTest::currentDataTag(), 400,
                                                      litOutside ? 20 : 0);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
        // The middle of the view, against the same file drawn as it is.
        auto centre = [&](const Scene &scene) {
            const QRgb p = m_offscreen.render(scene).pixel(kSize.width() / 2, kSize.height() / 2);
            return qRed(p) + qGreen(p) + qBlue(p);
        };
        Scene asIs = s;
        asIs.objects[0].faces = Faces::File;
        if (litOutside)
            QVERIFY2(centre(s) > centre(asIs) + 60,
                     qPrintable(QString("%1 against %2").arg(centre(s)).arg(centre(asIs))));
    }

    void normalLinesAreDrawnWhenAsked()
    {
        Scene s = sceneWith(kCorpus + "/PLY/cube.ply");
        auto yellowish = [](const QImage &img) {
            int n = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x) {
                    const QRgb p = img.pixel(x, y);
                    n += qRed(p) > 200 && qGreen(p) > 160 && qBlue(p) < 90;
                }
            return n;
        };
        s.objects[0].material.kd = s.objects[0].material.ka =
            glm::vec3(0.2f, 0.2f, 0.8f); // a blue cube
        s.objects[0].showNormals = false;
        const int without = yellowish(m_offscreen.render(s));
        s.objects[0].showNormals = true;
        const int with = yellowish(m_offscreen.render(s));
        QCOMPARE(without, 0);
        QVERIFY2(with > 20, qPrintable(QString::number(with)));
    }
};

QTEST_MAIN(TestMeshFiles)
#include "test_mesh_files.moc"
