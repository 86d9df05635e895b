// Frames rendered offscreen by the built-in shaders, pixel by pixel against the CPU reference
// (render/lighting through render/probe). A failing case writes its frame to
// build/tests/test-output/.
#include "gpu_mesh.h"
#include "presets.h"
#include "program.h"
#include "reference_compare.h"

#include <QGuiApplication>
#include <QTest>

using namespace lb;
using namespace lb::test;

class TestRenderReference : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

    void expectMatch(const Scene &scene, const QString &name, int minCompared, int minSpecular)
    {
        const QString failure =
            checkAgainstReference(m_offscreen, scene, name, minCompared, minSpecular);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
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
        int row = 0;
        for (int sh = 0; sh < 3; ++sh)
            for (int sp = 0; sp < 2; ++sp)
                for (int fr = 0; fr < 3; ++fr)
                    for (float w : {0.0f, 1.0f})
                        for (int pr = 0; pr < 2; ++pr)
                            if (inThisBuildsCases(row++))
                                QTest::newRow(qPrintable(QString("%1 %2 %3 w=%4 %5")
                                                             .arg(toName(Shading(sh)),
                                                                  toName(SpecularModel(sp)),
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
        s.lights[0].frame = LightFrame(frame);
        s.lights[0].position =
            w == 0.0f ? glm::vec4(1.0f, 1.5f, 2.0f, 0.0f) : glm::vec4(1.5f, 2.0f, 2.5f, 1.0f);
        s.objects[0].material.shininess = 20;
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
            s.objects[0].texture = true;
            s.objects[0].material.kd = s.objects[0].material.ka = glm::vec3(1.0f);
        }
        if (what == "texture gouraud")
            s.shading.shading = Shading::Gouraud;
        if (what == "lighting off") {
            s.shading.lighting = false;
            s.shading.vertexColors = true;
        }
        if (what.startsWith("cube"))
            s.objects[0].shape = Shape::Cube;
        if (what == "cube orthographic")
            s.shading.projection = Projection::Orthographic;
        if (what == "torus")
            s.objects[0].shape = Shape::Torus;
        if (what == "plane") {
            s.objects[0].shape = Shape::Plane;
            s.objects[0].rotationDegrees = {-30, 20, 0};
        }
        if (what == "shininess 300")
            s.objects[0].material.shininess = 300;
        const bool lit = s.shading.lighting;
        expectMatch(s, what, s.objects[0].shape == Shape::Cube ? 60 : 100, lit ? 1 : 0);
    }

    void fourLightsMatchTheReference_data()
    {
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("specular");
        for (int sh = 0; sh < 3; ++sh)
            for (int sp = 0; sp < 2; ++sp)
                QTest::newRow(qPrintable(toName(Shading(sh)) + " " + toName(SpecularModel(sp))))
                    << sh << sp;
    }

    void fourLightsMatchTheReference()
    {
        QFETCH(int, shading);
        QFETCH(int, specular);
        Scene s = testScene();
        s.shading.shading = Shading(shading);
        s.shading.specular = SpecularModel(specular);
        s.objects[0].material.shininess = 30;
        // One light in each frame, points and directions, coloured apart so that each one's
        // share shows; dim enough that the sum rarely saturates.
        const glm::vec4 positions[4] = {{1.5f, 2.0f, 2.5f, 1.0f},
                                        {-2.0f, 0.5f, 1.0f, 0.0f},
                                        {0.5f, -1.5f, 2.0f, 1.0f},
                                        {0.0f, 0.3f, 1.0f, 0.0f}};
        const LightFrame frames[4] = {LightFrame::World, LightFrame::Object, LightFrame::Camera,
                                      LightFrame::Camera};
        for (int i = 0; i < kMaxLights; ++i) {
            Light &l = s.lights[std::size_t(i)];
            l.enabled = true;
            l.position = positions[i];
            l.frame = frames[i];
            l.colors.ia = glm::vec3(0.03f);
            l.colors.id =
                glm::vec3(i == 1 ? 0.1f : 0.35f, i == 2 ? 0.1f : 0.3f, i == 0 ? 0.1f : 0.3f);
            l.colors.is = glm::vec3(0.4f);
        }
        expectMatch(s, QString("four lights ") + QTest::currentDataTag(), 100, 3);
    }

    // Issue 15's extensions of the model: terms switched off, attenuation and spotlights, in
    // both shadings and both specular models, with lights in each frame.
    void termsAttenuationAndSpotMatchTheReference_data()
    {
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("specular");
        QTest::addColumn<int>("terms"); // bits: 1 ambient, 2 diffuse, 4 specular
        QTest::addColumn<int>("frame");
        QTest::addColumn<bool>("attenuated");
        QTest::addColumn<bool>("spot");
        int row = 0;
        const auto add = [&](const QString &name, int sh, int sp, int terms, int fr,
                             bool attenuated, bool spot) {
            if (inThisBuildsCases(row++))
                QTest::newRow(qPrintable(name)) << sh << sp << terms << fr << attenuated << spot;
        };
        for (int sh = 0; sh < 3; ++sh)
            for (int sp = 0; sp < 2; ++sp) {
                const QString prefix = toName(Shading(sh)) + " " + toName(SpecularModel(sp));
                for (int terms : {1, 2, 4, 3, 6})
                    add(prefix + QString(" terms %1").arg(terms), sh, sp, terms, 1, false, false);
                for (int fr = 0; fr < 3; ++fr) {
                    const QString frame = " " + toName(LightFrame(fr));
                    add(prefix + frame + " attenuated", sh, sp, 7, fr, true, false);
                    add(prefix + frame + " spot", sh, sp, 7, fr, false, true);
                    add(prefix + frame + " spot attenuated diffuse", sh, sp, 2, fr, true, true);
                }
            }
    }
    void termsAttenuationAndSpotMatchTheReference()
    {
        QFETCH(int, shading);
        QFETCH(int, specular);
        QFETCH(int, terms);
        QFETCH(int, frame);
        QFETCH(bool, attenuated);
        QFETCH(bool, spot);
        Scene s = testScene();
        s.shading.shading = Shading(shading);
        s.shading.specular = SpecularModel(specular);
        s.shading.terms = {(terms & 1) != 0, (terms & 2) != 0, (terms & 4) != 0};
        Light &l = s.lights[0];
        l.frame = LightFrame(frame);
        l.position = {0.6f, 0.9f, 2.2f, 1.0f};
        l.colors.ia = glm::vec3(0.3f);
        if (attenuated)
            l.attenuation = {0.4f, 0.3f, 0.15f};
        if (spot) // aimed past the middle, so that the cone's edge crosses the object
            l.spot = {glm::vec3(-0.35f, -0.3f, -1.0f), 22.0f, 6.0f};
        const int minSpecular = (terms & 4) && !spot ? 3 : 0;
        expectMatch(s, QTest::currentDataTag(), spot ? 60 : 100, minSpecular);
        if (!spot)
            return;
        // The cone leaves part of the object dark (ambient included): it is not all lit.
        int dark = 0;
        const QImage frameImage = m_offscreen.render(s);
        const QRgb background = frameImage.pixel(0, 0);
        for (int y = 0; y < frameImage.height(); y += 4)
            for (int x = 0; x < frameImage.width(); x += 4)
                if (const QRgb p = frameImage.pixel(x, y); p != background && qRed(p) == 0)
                    ++dark;
        QVERIFY2(dark > 50, qPrintable(QString("%1 dark samples").arg(dark)));
    }

    // The Show choice: light 1's vectors and numbers instead of the colour, with light 2 on
    // too (it must not count), in both shadings and each frame of light 1.
    void showChoicesMatchTheReference_data()
    {
        QTest::addColumn<int>("show");
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("specular");
        QTest::addColumn<int>("frame");
        for (int show = 1; show <= int(ShowChoice::Attenuation); ++show)
            for (int sh = 0; sh < 3; ++sh)
                for (int fr = 0; fr < 3; ++fr) {
                    const int sp = (show + fr) % 2; // both specular models across the rows
                    QTest::newRow(
                        qPrintable(QString("%1 %2 %3 %4")
                                       .arg(toName(ShowChoice(show)), toName(Shading(sh)),
                                            toName(SpecularModel(sp)), toName(LightFrame(fr)))))
                        << show << sh << sp << fr;
                }
    }
    void showChoicesMatchTheReference()
    {
        QFETCH(int, show);
        QFETCH(int, shading);
        QFETCH(int, specular);
        QFETCH(int, frame);
        Scene s = testScene();
        s.shading.show = ShowChoice(show);
        s.shading.shading = Shading(shading);
        s.shading.specular = SpecularModel(specular);
        s.objects[0].material.shininess = 8;
        s.lights[0].frame = LightFrame(frame);
        s.lights[0].position = {0.8f, 1.1f, 1.9f, 1.0f};
        s.lights[0].attenuation = {0.3f, 0.4f, 0.2f};
        s.lights[1].enabled = true; // on, and not what is shown
        expectMatch(s, QTest::currentDataTag(), 100, 0);
        // Not the lit colour: the picture changes with the choice.
        Scene lit = s;
        lit.shading.show = ShowChoice::Colour;
        QVERIFY(largestDifference(m_offscreen.render(s), m_offscreen.render(lit)) > 20);
    }

    void aLightSwitchedOffAddsNothing()
    {
        Scene one = testScene();
        Scene two = one;
        two.lights[1].enabled = false;
        two.lights[1].colors = LightColors{}; // bright, but off
        const QImage a = m_offscreen.render(one);
        QCOMPARE(largestDifference(a, m_offscreen.render(two)), 0);
        two.lights[1].enabled = true;
        QVERIFY(largestDifference(a, m_offscreen.render(two)) > 20); // and on, it shows
    }

    // GL's counts are 32-bit ints and a mesh may hold 2^32 indices (issue 13): a mesh over the
    // count of one draw call is drawn in pieces. Pieces of one triangle, and of sizes that are
    // no multiple of 3 (taken down to whole triangles), draw the same pixels, normal lines
    // included.
    void meshesDrawnInPiecesDrawTheSamePixels()
    {
        Scene s = testScene();
        s.objects[0].showNormals = true;
        const QImage whole = m_offscreen.render(s);
        for (std::uint64_t most : {3, 100, 1000}) {
            m_offscreen.renderer().setMaxPerDraw(most);
            const QImage pieces = m_offscreen.render(s);
            m_offscreen.renderer().setMaxPerDraw(GpuMesh::kMaxPerDraw);
            QCOMPARE(largestDifference(whole, pieces), 0);
        }
        QCOMPARE(drawRanges(10, 3, 3).size(), std::size_t(4));
        QCOMPARE(drawRanges(10, 3, 3).back().first, std::uint64_t(9));
        QCOMPARE(drawRanges(10, 3, 3).back().count, GLsizei(1));
        const std::vector<DrawRange> big = drawRanges(0xffffffffull, GpuMesh::kMaxPerDraw, 3);
        QCOMPARE(big.size(), std::size_t(3));
        QCOMPARE(big[0].count, GLsizei(0x7ffffffe));
        QCOMPARE(big[2].first + std::uint64_t(big[2].count), 0xffffffffull);
    }

    // The built-in programs are compiled for the lights a scene uses (issue 14: one light cost
    // four passes of the loop). Each count draws what the shipped four-light text draws when
    // it is a user's program.
    void builtInsForFewerLightsDrawAsTheShippedText_data()
    {
        QTest::addColumn<bool>("gouraud");
        QTest::addColumn<QList<int>>("on"); // lights switched on, 0-based
        for (bool gouraud : {false, true}) {
            const char *name = gouraud ? "gouraud" : "phong";
            QTest::addRow("%s, light 1", name) << gouraud << QList<int>{0};
            QTest::addRow("%s, lights 1 and 3", name) << gouraud << QList<int>{0, 2};
            QTest::addRow("%s, light 2 alone", name) << gouraud << QList<int>{1};
            QTest::addRow("%s, all four", name) << gouraud << QList<int>{0, 1, 2, 3};
            QTest::addRow("%s, none", name) << gouraud << QList<int>{};
        }
    }

    void builtInsForFewerLightsDrawAsTheShippedText()
    {
        QFETCH(bool, gouraud);
        QFETCH(QList<int>, on);
        Scene s = testScene();
        s.shading.shading = gouraud ? Shading::Gouraud : Shading::Phong;
        for (int i = 0; i < kMaxLights; ++i) {
            Light &l = s.lights[std::size_t(i)];
            l.enabled = on.contains(i);
            l.position = glm::vec4(1.5f - float(i), 1.0f + 0.3f * float(i), 2.0f, 1.0f);
            l.colors.id = glm::vec3(0.25f * float(i + 1), 0.5f, 0.3f);
        }
        int expected = 1;
        for (int i : on)
            expected = std::max(expected, i + 1);
        QCOMPARE(builtInLightCount(s), expected);

        const QImage specialised = m_offscreen.render(s);
        // The shipped text with a comment added: a user's program, drawn as it is written.
        const Preset &shipped = builtInPreset(gouraud);
        QVERIFY(
            m_offscreen.useProgram(shipped.vertexSource(), shipped.fragmentSource() + "\n// mine\n")
                .ok());
        const QImage asWritten = m_offscreen.render(s);
        QVERIFY(largestDifference(specialised, asWritten) <= 1);
        // The shipped text itself (what the editor holds until it is edited) is drawn
        // specialised too.
        QVERIFY(m_offscreen.useProgram(shipped.vertexSource(), shipped.fragmentSource()).ok());
        QCOMPARE(largestDifference(specialised, m_offscreen.render(s)), 0);
        m_offscreen.renderer().clearUserProgram();
    }

    void specialisationNeedsTheDefineLine()
    {
        QCOMPARE(
            withDefine("#version 330 core\n#define MAX_LIGHTS 4\nvoid main() {}", "MAX_LIGHTS", 2),
            QString("#version 330 core\n#define MAX_LIGHTS 2\nvoid main() {}"));
        QVERIFY(withDefine("void main() {}", "MAX_LIGHTS", 2).isEmpty());
        for (bool gouraud : {false, true}) {
            const Preset &p = builtInPreset(gouraud);
            const QString &lit = gouraud ? p.vertexSource() : p.fragmentSource();
            QVERIFY(!withDefine(lit, "MAX_LIGHTS", 1).isEmpty());
            QVERIFY(!withDefine(lit, "LIGHT_FACTORS", 0).isEmpty());
        }
        // Attenuation and spot are compiled in only for a light that is on and uses them
        // (attenuation only for a point light).
        Scene s;
        QVERIFY(!builtInNeedsLightFactors(s));
        s.lights[1].spot.cutoffDegrees = 30.0f; // light 2 is off
        QVERIFY(!builtInNeedsLightFactors(s));
        s.lights[1].enabled = true;
        QVERIFY(builtInNeedsLightFactors(s));
        s = Scene{};
        s.lights[0].attenuation = {1.0f, 0.5f, 0.0f};
        QVERIFY(builtInNeedsLightFactors(s));
        s.lights[0].position.w = 0.0f;
        QVERIFY(!builtInNeedsLightFactors(s));
        s.lights[0].spot.cutoffDegrees = 40.0f; // a directional light's spot still applies
        QVERIFY(builtInNeedsLightFactors(s));
        // Show attenuation shows light 1's, on or off.
        s = Scene{};
        s.lights[0].enabled = false;
        s.lights[0].attenuation = {1.0f, 0.5f, 0.0f};
        s.lights[1].enabled = true;
        QVERIFY(!builtInNeedsLightFactors(s));
        s.shading.show = ShowChoice::Attenuation;
        QVERIFY(builtInNeedsLightFactors(s));
    }

    // Flat shading is its own picture: one colour per triangle, so it differs from Gouraud's
    // interpolation inside the triangles (and each is what the reference says, above).
    void flatDiffersFromGouraud()
    {
        Scene s = testScene();
        s.shading.shading = Shading::Gouraud;
        const QImage gouraud = m_offscreen.render(s);
        s.shading.shading = Shading::Flat;
        const QImage flat = m_offscreen.render(s);
        QVERIFY(largestDifference(gouraud, flat) > 20);
        s.shading.shading = Shading::Phong;
        QVERIFY(largestDifference(m_offscreen.render(s), flat) > 20);
    }

    void gouraudAndPhongDifferAtTheHighlight()
    {
        Scene s; // the default scene: the coarse sphere of the window
        s.showLight = false;
        const QImage phong = m_offscreen.render(s);
        const QPoint peak = brightestGreen(phong); // the middle of Phong's highlight
        s.shading.shading = Shading::Gouraud;
        const QImage gouraud = m_offscreen.render(s);
        const int diff = std::abs(qGreen(gouraud.pixel(peak)) - qGreen(phong.pixel(peak)));
        QVERIFY2(
            diff >= 20,
            qPrintable(
                QString("only %1/255 apart at (%2, %3)").arg(diff).arg(peak.x()).arg(peak.y())));
        // And each is what the reference says for its own mode there.
        const ProbedObjects objects = m_offscreen.probedObjects(s);
        for (Shading mode : {Shading::Phong, Shading::Gouraud}) {
            s.shading.shading = mode;
            const ProbeResult p = probePixel(s, objects, kSize, peak);
            const QImage &img = mode == Shading::Phong ? phong : gouraud;
            QVERIFY(p.hit);
            QVERIFY(channelDifference(img.pixel(peak), p.reference) <= kTolerance);
        }
    }

    // Back-face culling (issue 14, Object panel): a closed mesh draws the same pixels with it
    // as without, also mirrored by a negative scale (whose front faces reach the screen
    // clockwise), and still matches the reference.
    void cullingLeavesClosedMeshesAsTheyAre_data()
    {
        QTest::addColumn<int>("shape");
        QTest::addColumn<float>("scaleX");
        QTest::newRow("sphere") << int(Shape::Sphere) << 1.3f;
        QTest::newRow("sphere mirrored") << int(Shape::Sphere) << -1.3f;
        QTest::newRow("torus mirrored") << int(Shape::Torus) << -1.0f;
        QTest::newRow("cube") << int(Shape::Cube) << 1.0f;
    }
    void cullingLeavesClosedMeshesAsTheyAre()
    {
        QFETCH(int, shape);
        QFETCH(float, scaleX);
        Scene s = testScene();
        s.objects[0].shape = Shape(shape);
        s.objects[0].scale.x = scaleX;
        const QImage all = m_offscreen.render(s);
        s.objects[0].cullBackFaces = true;
        QCOMPARE(largestDifference(all, m_offscreen.render(s)), 0);
        expectMatch(s, QTest::currentDataTag(), 100, 1);
    }

    // An open mesh seen from behind: culled, nothing is drawn and the probe finds nothing;
    // not culled, both see its back. A mirrored plane facing the camera is drawn either way.
    void culledBackFacesAreNeitherDrawnNorProbed()
    {
        Scene s = testScene();
        s.objects[0].shape = Shape::Plane;
        s.objects[0].scale = glm::vec3(1.0f);
        s.objects[0].rotationDegrees = {0.0f, 180.0f, 0.0f};
        const QPoint centre(kSize.width() / 2, kSize.height() / 2);
        const auto probeCentre = [&](const Scene &scene) {
            return probePixel(scene, m_offscreen.probedObjects(scene), kSize, centre);
        };
        const QRgb background = m_offscreen.render(s).pixel(0, 0);
        QVERIFY(m_offscreen.render(s).pixel(centre) != background);
        QVERIFY(probeCentre(s).hit);
        s.objects[0].cullBackFaces = true;
        const QImage culled = m_offscreen.render(s);
        for (int y = 0; y < culled.height(); y += 4)
            for (int x = 0; x < culled.width(); x += 4)
                QCOMPARE(culled.pixel(x, y), background);
        QVERIFY(!probeCentre(s).hit);

        s.objects[0].rotationDegrees = glm::vec3(0.0f);
        s.objects[0].scale.x = -1.0f;
        QVERIFY(m_offscreen.render(s).pixel(centre) != background);
        QVERIFY(probeCentre(s).hit);
        expectMatch(s, "mirrored plane, culled", 100, 0);
    }

    // A spotlight's marker adds rays along its cone: more of the frame changes than for the
    // point light's sphere alone, and nothing when the markers are hidden.
    void spotlightMarkerShowsTheCone()
    {
        Scene s;
        s.lights[0].position = {0.0f, 1.6f, 0.0f, 1.0f};
        s.lights[0].spot = {{0.0f, -1.0f, 0.0f}, 30.0f, 2.0f};
        const auto markerPixels = [&](const Scene &scene) {
            Scene hidden = scene;
            hidden.showLight = false;
            const QImage with = m_offscreen.render(scene), without = m_offscreen.render(hidden);
            int changed = 0;
            for (int y = 0; y < with.height(); ++y)
                for (int x = 0; x < with.width(); ++x)
                    changed += with.pixel(x, y) != without.pixel(x, y);
            return changed;
        };
        Scene point = s;
        point.lights[0].spot.cutoffDegrees = 180.0f;
        const int sphere = markerPixels(point), cone = markerPixels(s);
        QVERIFY2(sphere > 10 && cone > sphere + 20,
                 qPrintable(QString("sphere %1 pixels, with the cone %2").arg(sphere).arg(cone)));
    }

    void lightMarkerIsDrawnUnlit()
    {
        Scene s;
        s.lights[0].frame = LightFrame::Camera;
        s.lights[0].position = {0, 0, -2.5f,
                                1}; // in front of the camera, between it and the sphere
        s.lights[0].colors.id = {0.0f, 0.35f, 0.7f};
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
