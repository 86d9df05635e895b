// Frames rendered offscreen by the built-in shaders, pixel by pixel against the CPU reference
// (render/lighting through render/probe). A failing case writes its frame to test-output/.
#include "offscreen.h"
#include "probe.h"

#include <QDir>
#include <QGuiApplication>
#include <QRegularExpression>
#include <QTest>

#include <glm/geometric.hpp>

using namespace lb;

namespace {

constexpr int kTolerance = 2; // per channel, out of 255
const QSize kSize(320, 240);

struct Comparison
{
    int compared = 0;
    int withSpecular = 0; // samples where the highlight contributes visibly
    int worst = 0;
    QPoint worstAt;
    QString worstText;
};

int channelDifference(QRgb gpu, const glm::vec3 &reference)
{
    const int r = int(std::lround(reference.r * 255)), g = int(std::lround(reference.g * 255)),
              b = int(std::lround(reference.b * 255));
    return std::max({std::abs(qRed(gpu) - r), std::abs(qGreen(gpu) - g), std::abs(qBlue(gpu) - b)});
}

// Compares a grid of pixels. Pixels on a silhouette or a crease (a neighbour two pixels away
// misses the object or sees another face) are skipped: there the rasteriser and the ray may
// rightly pick different triangles.
Comparison compareWithReference(OffscreenRenderer &offscreen, const Scene &scene,
                                const QImage &frame, int step = 5)
{
    const Mesh &mesh = offscreen.renderer().meshFor(scene.object);
    const CheckerTexture &texture = offscreen.renderer().checkerTexture();
    Comparison c;
    for (int y = 3; y < kSize.height() - 3; y += step) {
        for (int x = 3; x < kSize.width() - 3; x += step) {
            const ProbeResult p = probePixel(scene, mesh, texture, kSize, QPoint(x, y));
            if (!p.hit)
                continue;
            bool interior = true;
            for (const QPoint d : {QPoint(2, 0), QPoint(-2, 0), QPoint(0, 2), QPoint(0, -2)}) {
                const ProbeResult n = probePixel(scene, mesh, texture, kSize, QPoint(x, y) + d);
                interior = interior && n.hit && glm::dot(n.normal, p.normal) > 0.98f;
            }
            if (!interior)
                continue;
            ++c.compared;
            if (p.terms.specular.r > 0.05f)
                ++c.withSpecular;
            const int diff = channelDifference(frame.pixel(x, y), p.reference);
            if (diff > c.worst) {
                c.worst = diff;
                c.worstAt = QPoint(x, y);
                const QRgb g = frame.pixel(x, y);
                c.worstText = QString("gpu (%1,%2,%3) reference (%4,%5,%6)")
                                  .arg(qRed(g))
                                  .arg(qGreen(g))
                                  .arg(qBlue(g))
                                  .arg(p.reference.r * 255)
                                  .arg(p.reference.g * 255)
                                  .arg(p.reference.b * 255);
            }
        }
    }
    return c;
}

QString saveForInspection(const QImage &frame, const QString &name)
{
    QDir().mkpath("test-output");
    QString file = name;
    file.replace(QRegularExpression("[^A-Za-z0-9_-]+"), "_");
    const QString path = QDir("test-output").absoluteFilePath(file + ".png");
    frame.save(path);
    return path;
}

// A scene where the normal matrix matters: rotated and scaled non-uniformly.
Scene testScene()
{
    Scene s;
    s.showLight = false;
    s.object.tessellation = 24;
    s.object.rotationDegrees = {20, 30, 0};
    s.object.scale = {1.2f, 0.8f, 1.0f};
    s.camera.distance = 3.8f; // the object fills most of the small frame
    return s;
}

} // namespace

class TestRenderReference : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

    // minSpecular: how many compared pixels must show the highlight, so that a case whose
    // highlight is out of view cannot pass by testing only ambient and diffuse.
    void expectMatch(const Scene &scene, const QString &name, int minCompared, int minSpecular)
    {
        const QImage frame = m_offscreen.render(scene);
        const Comparison c = compareWithReference(m_offscreen, scene, frame);
        QVERIFY2(c.compared >= minCompared,
                 qPrintable(QString("only %1 pixels compared").arg(c.compared)));
        qInfo("%d pixels compared (%d with a highlight), worst %d/255", c.compared, c.withSpecular,
              c.worst);
        QVERIFY2(c.withSpecular >= minSpecular,
                 qPrintable(QString("only %1 pixels with a highlight").arg(c.withSpecular)));
        if (c.worst > kTolerance) {
            const QString path = saveForInspection(frame, name);
            QFAIL(qPrintable(QString("pixel (%1, %2) is off by %3/255: %4; frame in %5")
                                 .arg(c.worstAt.x())
                                 .arg(c.worstAt.y())
                                 .arg(c.worst)
                                 .arg(c.worstText, path)));
        }
    }

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void everyVariantMatchesTheReference_data()
    {
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("specular");
        QTest::addColumn<int>("frame");
        QTest::addColumn<float>("w");
        QTest::addColumn<int>("projection");
        for (int sh = 0; sh < 2; ++sh)
            for (int sp = 0; sp < 2; ++sp)
                for (int fr = 0; fr < 3; ++fr)
                    for (float w : {0.0f, 1.0f})
                        for (int pr = 0; pr < 2; ++pr)
                            QTest::newRow(
                                qPrintable(QString("%1 %2 %3 w=%4 %5")
                                               .arg(toName(Shading(sh)), toName(SpecularModel(sp)),
                                                    toName(LightFrame(fr)))
                                               .arg(w)
                                               .arg(toName(Projection(pr)))))
                                << sh << sp << fr << w << pr;
    }

    void everyVariantMatchesTheReference()
    {
        QFETCH(int, shading);
        QFETCH(int, specular);
        QFETCH(int, frame);
        QFETCH(float, w);
        QFETCH(int, projection);
        Scene s = testScene();
        s.shading.shading = Shading(shading);
        s.shading.specular = SpecularModel(specular);
        s.shading.projection = Projection(projection);
        s.light.frame = LightFrame(frame);
        s.light.position =
            w == 0.0f ? glm::vec4(1.0f, 1.5f, 2.0f, 0.0f) : glm::vec4(1.5f, 2.0f, 2.5f, 1.0f);
        s.material.shininess = 20;
        expectMatch(s, QTest::currentDataTag(), 100, 3);
    }

    void switchesAndShapesMatchTheReference_data()
    {
        QTest::addColumn<QString>("what");
        for (const char *name : {"vertex colours", "texture", "texture gouraud", "lighting off",
                                 "cube", "cube orthographic", "torus", "plane", "shininess 300"})
            QTest::newRow(name) << QString(name);
    }

    void switchesAndShapesMatchTheReference()
    {
        QFETCH(QString, what);
        Scene s = testScene();
        if (what == "vertex colours")
            s.shading.vertexColors = true;
        if (what.startsWith("texture")) {
            s.shading.texture = true;
            s.material.kd = s.material.ka = glm::vec3(1.0f);
        }
        if (what == "texture gouraud")
            s.shading.shading = Shading::Gouraud;
        if (what == "lighting off") {
            s.shading.lighting = false;
            s.shading.vertexColors = true;
        }
        if (what.startsWith("cube"))
            s.object.shape = Shape::Cube;
        if (what == "cube orthographic")
            s.shading.projection = Projection::Orthographic;
        if (what == "torus")
            s.object.shape = Shape::Torus;
        if (what == "plane") {
            s.object.shape = Shape::Plane;
            s.object.rotationDegrees = {-30, 20, 0};
        }
        if (what == "shininess 300")
            s.material.shininess = 300;
        const bool lit = s.shading.lighting;
        expectMatch(s, what, s.object.shape == Shape::Cube ? 60 : 100, lit ? 1 : 0);
    }

    void gouraudAndPhongDifferAtTheHighlight()
    {
        Scene s; // the default scene: the coarse sphere of the window
        s.showLight = false;
        const QImage phong = m_offscreen.render(s);
        // The brightest pixel of Phong's highlight.
        QPoint peak;
        int best = -1;
        for (int y = 0; y < phong.height(); ++y)
            for (int x = 0; x < phong.width(); ++x)
                if (const int v = qGreen(phong.pixel(x, y)); v > best) {
                    best = v;
                    peak = QPoint(x, y);
                }
        s.shading.shading = Shading::Gouraud;
        const QImage gouraud = m_offscreen.render(s);
        const int diff = std::abs(qGreen(gouraud.pixel(peak)) - qGreen(phong.pixel(peak)));
        QVERIFY2(
            diff >= 20,
            qPrintable(
                QString("only %1/255 apart at (%2, %3)").arg(diff).arg(peak.x()).arg(peak.y())));
        // And each is what the reference says for its own mode there.
        const Mesh &mesh = m_offscreen.renderer().meshFor(s.object);
        for (Shading mode : {Shading::Phong, Shading::Gouraud}) {
            s.shading.shading = mode;
            const ProbeResult p =
                probePixel(s, mesh, m_offscreen.renderer().checkerTexture(), kSize, peak);
            const QImage &img = mode == Shading::Phong ? phong : gouraud;
            QVERIFY(p.hit);
            QVERIFY(channelDifference(img.pixel(peak), p.reference) <= kTolerance);
        }
    }

    void lightMarkerIsDrawnUnlit()
    {
        Scene s;
        s.light.frame = LightFrame::Camera;
        s.light.position = {0, 0, -2.5f, 1}; // in front of the camera, between it and the sphere
        s.light.colors.id = {0.0f, 0.35f, 0.7f};
        const QImage frame = m_offscreen.render(s);
        // The marker's colour is Id at full brightness: (0, 0.5, 1).
        const QRgb centre = frame.pixel(kSize.width() / 2, kSize.height() / 2);
        QCOMPARE(qRed(centre), 0);
        QVERIFY(std::abs(qGreen(centre) - 128) <= 1);
        QCOMPARE(qBlue(centre), 255);
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestRenderReference test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_render_reference.moc"
