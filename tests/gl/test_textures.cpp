// Image textures: a PNG read as a texture (texture_file.h) on a plane seen at a grazing angle
// (minified far away, so mipmap levels change across it), a torus (texture coordinates up to
// 4: the wrap shows) and a cube, drawn by the built-in shaders with every wrap, filter and
// mipmap choice, and checked pixel by pixel against the CPU reference's lookup; and the
// files a texture must refuse.
#include "reference_compare.h"
#include "texture_file.h"

#include <QGuiApplication>
#include <QPainter>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;
using namespace lb::test;

namespace {

// 512 x 256 texels: colour gradients (linear filtering shows) under fine stripes and a few
// sharp squares (nearest filtering and mipmaps show).
QImage testImage()
{
    QImage image(512, 256, QImage::Format_RGB32);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const bool stripe = (x / 4 + y / 8) % 2 == 0;
            image.setPixel(x, y, qRgb(x / 2, stripe ? 230 : 30, 255 - y));
        }
    QPainter painter(&image);
    painter.fillRect(32, 32, 48, 48, QColor(250, 250, 60));
    painter.fillRect(400, 160, 64, 40, QColor(20, 160, 20));
    return image;
}

} // namespace

class TestTextures : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;
    QTemporaryDir m_dir;
    QString m_imagePath;

    Scene texturedScene(const TextureSampling &sampling)
    {
        Scene s = testScene();
        ObjectSettings plane;
        plane.shape = Shape::Plane;
        plane.tessellation = 4;
        plane.rotationDegrees = {-84, 0, 0}; // nearly edge-on: minified towards the back
        plane.scale = {2.0f, 6.0f, 1.0f};
        plane.translation = {0.0f, -0.9f, -3.0f};
        ObjectSettings torus;
        torus.shape = Shape::Torus;
        torus.tessellation = 24;
        torus.rotationDegrees = {60, 0, 0};
        torus.scale = glm::vec3(0.7f);
        torus.translation = {-1.0f, 0.2f, 0.0f};
        ObjectSettings cube;
        cube.shape = Shape::Cube;
        cube.rotationDegrees = {20, 30, 0};
        cube.scale = glm::vec3(0.45f);
        cube.translation = {1.1f, 0.3f, 0.2f};
        s.objects = {plane, torus, cube};
        for (ObjectSettings &o : s.objects) {
            o.material.ka = o.material.kd = glm::vec3(0.9f); // the texture's own colours
            o.texture = true;
            o.textureFile = m_imagePath;
            o.sampling = sampling;
        }
        s.camera.distance = 4.5f;
        s.camera.pitchDegrees = 12.0f;
        s.camera.yawDegrees = 0.0f;
        s.camera.target = glm::vec3(0.0f);
        return s;
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_offscreen.initialize(kSize).isEmpty(), "no OpenGL");
        QVERIFY(m_dir.isValid());
        m_imagePath = m_dir.filePath("stripes.png");
        QVERIFY(testImage().save(m_imagePath));
        const TextureFileRead read = readTextureFile(m_imagePath);
        QVERIFY2(read.texture, qPrintable(read.error));
        QCOMPARE(read.texture->image().size(), QSize(512, 256));
        QCOMPARE(read.texture->levelCount(), 10); // 512 x 256 down to 1 x 1
        m_offscreen.addTextureFile(m_imagePath, read.texture);
    }

    void imageTexturesMatchTheReference_data()
    {
        QTest::addColumn<int>("wrap");
        QTest::addColumn<int>("filter");
        QTest::addColumn<bool>("mipmaps");
        QTest::addColumn<int>("shading");
        // Every sampling with Phong shading; Gouraud (the texture is read per fragment all the
        // same) for two of them. Few rows, sparse pixels: the sanitizer build runs these too.
        const auto row = [](int w, int f, bool m, Shading sh) {
            QTest::newRow(qPrintable(QString("%1 %2%3 %4")
                                         .arg(toName(TextureWrap(w)), toName(TextureFilter(f)),
                                              m ? " mipmaps" : "", toName(sh))))
                << w << f << m << int(sh);
        };
        for (int w = 0; w < 2; ++w)
            for (int f = 0; f < 2; ++f)
                for (int m = 0; m < 2; ++m)
                    row(w, f, bool(m), Shading::Phong);
        row(0, 0, true, Shading::Gouraud);
        row(1, 1, true, Shading::Gouraud);
    }

    void imageTexturesMatchTheReference()
    {
        QFETCH(int, wrap);
        QFETCH(int, filter);
        QFETCH(bool, mipmaps);
        QFETCH(int, shading);
        Scene s = texturedScene({TextureWrap(wrap), TextureFilter(filter), mipmaps});
        s.shading.shading = Shading(shading);
        const QImage frame = m_offscreen.render(s);
        const Comparison c = compareWithReference(m_offscreen, s, frame, 4);
        const QString name = QTest::currentDataTag();
        if (qEnvironmentVariableIsSet("LB_SAVE_FRAMES"))
            saveForInspection(frame, "texture " + name);
        qInfo("%s: %d pixels compared, worst %d/255", qPrintable(name), c.compared, c.worst);
        // Trilinear blends two levels by the level of detail, where llvmpipe's differs from
        // the exact log2 by a few hundredths where the coordinates change fast: 3/255 on a
        // handful of pixels between levels that differ by a third of the range.
        const int tolerance =
            mipmaps && TextureFilter(filter) == TextureFilter::Linear ? kTolerance + 1 : kTolerance;
        QVERIFY2(c.worst <= tolerance,
                 qPrintable(QString("(%1, %2) off by %3: %4; frame in %5")
                                .arg(c.worstAt.x())
                                .arg(c.worstAt.y())
                                .arg(c.worst)
                                .arg(c.worstText, saveForInspection(frame, "texture " + name))));
        QVERIFY2(c.compared >= ofThisGrid(1200), qPrintable(QString::number(c.compared)));
    }

    // The scene covers what it tests: the level of detail changes by more than a level across
    // the plane, and each choice changes the picture.
    void eachChoiceShowsInTheScene()
    {
        const Scene s = texturedScene({});
        const ProbedObjects objects = m_offscreen.probedObjects(s);
        float least = 100.0f, most = -100.0f;
        for (int y = 0; y < kSize.height(); y += 4)
            for (int x = 0; x < kSize.width(); x += 4)
                if (const ProbeResult p = probePixel(s, objects, kSize, {x, y});
                    p.hit && p.object == 0) {
                    least = std::min(least, p.lod);
                    most = std::max(most, p.lod);
                }
        qInfo("the plane's level of detail: %.2f to %.2f", double(least), double(most));
        QVERIFY(least < 1.0f);
        QVERIFY(most > 2.0f);

        const QImage plain = m_offscreen.render(s);
        const auto differs = [&](const TextureSampling &sampling) {
            return largestDifference(plain, m_offscreen.render(texturedScene(sampling)));
        };
        QVERIFY(differs({TextureWrap::Clamp, TextureFilter::Linear, false}) > 40);
        QVERIFY(differs({TextureWrap::Repeat, TextureFilter::Nearest, false}) > 40);
        QVERIFY(differs({TextureWrap::Repeat, TextureFilter::Linear, true}) > 40);
        // And the image is drawn, not the checker.
        Scene checker = s;
        for (ObjectSettings &o : checker.objects)
            o.textureFile.clear();
        QVERIFY(largestDifference(plain, m_offscreen.render(checker)) > 40);
    }
};

QTEST_MAIN(TestTextures)
#include "test_textures.moc"
