// User programs: the reference files' shaders typed in as they stand compile, link and draw
// what the model says; bad sources give a message on the right line and the last good
// program keeps drawing.
#include "presets.h"
#include "reference_compare.h"
#include "webgl1_translation.h"

#include <QFile>
#include <QGuiApplication>
#include <QTest>

using namespace lb;
using namespace lb::test;

namespace {

QString fixture(const QString &name)
{
    QFile f(QStringLiteral(LB_TEST_DATA "/") + name);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("missing fixture %s", qPrintable(name));
    return QString::fromUtf8(f.readAll());
}

const char *kPlainVertex = "attribute vec4 vPosition;\n"
                           "uniform mat4 mModelView;\n"
                           "uniform mat4 mProjection;\n"
                           "void main() { gl_Position = mProjection * mModelView * vPosition; }\n";
const char *kPlainVertex330 =
    "#version 330 core\n"
    "in vec4 vPosition;\n"
    "uniform mat4 mModelView;\n"
    "uniform mat4 mProjection;\n"
    "void main() { gl_Position = mProjection * mModelView * vPosition; }\n";
const char *kWhiteFragment = "precision mediump float;\n"
                             "void main() { gl_FragColor = vec4(1.0); }\n";

int imageDifference(const QImage &a, const QImage &b)
{
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            worst =
                std::max(worst, channelDifference(a.pixel(x, y), glm::vec3(qRed(b.pixel(x, y)),
                                                                           qGreen(b.pixel(x, y)),
                                                                           qBlue(b.pixel(x, y))) /
                                                                     255.0f));
    return worst;
}

} // namespace

class TestUserShaders : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void cleanup() { m_offscreen.useProgram({}, {}); } // an empty source never replaces

    // The view is opaque, as a desktop window's framebuffer: a program's alpha changes nothing,
    // whether below 1 or left undefined by a vec3 output (opengl-tutorial.org's `out vec3
    // color`, which llvmpipe writes with alpha 0 and which read as premultiplied was black).
    void alphaIsIgnored_data()
    {
        QTest::addColumn<QString>("vertex");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("WebGL 1, alpha 0.5")
            << QString(kPlainVertex)
            << QString("precision mediump float;\n"
                       "void main() { gl_FragColor = vec4(0.25, 0.5, 0.125, 0.5); }\n");
        QTest::newRow("3.30, alpha 0")
            << QString(kPlainVertex330)
            << QString("#version 330 core\nout vec4 c;\n"
                       "void main() { c = vec4(0.25, 0.5, 0.125, 0.0); }\n");
        QTest::newRow("3.30, out vec3")
            << QString(kPlainVertex330)
            << QString("#version 330 core\nout vec3 color;\n"
                       "void main() { color = vec3(0.25, 0.5, 0.125); }\n");
    }

    void alphaIsIgnored()
    {
        QFETCH(QString, vertex);
        QFETCH(QString, fragment);
        const ProgramBuild build = m_offscreen.useProgram(vertex, fragment);
        QVERIFY2(build.ok(), qPrintable(build.log()));
        Scene s;
        s.showLight = false;
        const QImage frame = m_offscreen.render(s);
        QCOMPARE(frame.format(), QImage::Format_RGB32);
        const QRgb centre = frame.pixel(kSize.width() / 2, kSize.height() / 2);
        QVERIFY2(std::abs(qRed(centre) - 64) <= 1 && std::abs(qGreen(centre) - 128) <= 1 &&
                     std::abs(qBlue(centre) - 32) <= 1,
                 qPrintable(QString::number(centre, 16)));
    }

    void slidesShadersAsPasted_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("tolerance");
        QTest::newRow("gouraud") << "gouraud" << int(Shading::Gouraud) << kTolerance;
        // The slides' Phong shading interpolates the unit vector L from the vertices instead
        // of recomputing it per fragment as the reference does; for their point light that
        // costs a few levels near the highlight.
        QTest::newRow("phong") << "phong" << int(Shading::Phong) << 6;
    }

    void slidesShadersAsPasted()
    {
        QFETCH(QString, name);
        QFETCH(int, shading);
        QFETCH(int, tolerance);
        // The Presets menu's copies: the slides' code as printed, under a comment header.
        const Preset preset{name, ":/shaders/presets/slides_" + name};
        // As pasted, and translated to GLSL 3.30 (drivers without "#version 100").
        for (const bool translate : {false, true}) {
            setWebGl1TranslationForced(translate);
            const ProgramBuild build =
                m_offscreen.useProgram(preset.vertexSource(), preset.fragmentSource());
            setWebGl1TranslationForced(false);
            QVERIFY2(build.ok(), qPrintable(build.log()));
            QVERIFY2(build.diagnostics.empty(), qPrintable(build.log()));
            // The slides' constants are the default scene: their light (0, 1.8, 1.3, 1) in
            // world coordinates, their red plastic, Blinn-Phong; their V = (0,0,1) is the
            // parallel one.
            Scene s = testScene();
            s.shading.shading = Shading(shading);
            s.shading.projection = Projection::Orthographic;
            const QString failure = checkAgainstReference(
                m_offscreen, s, "slides " + name + (translate ? ", translated" : ""), 100, 5,
                tolerance);
            QVERIFY2(failure.isEmpty(), qPrintable(failure));
        }
    }

    void everyPresetBuilds()
    {
        for (const Preset &p : presets()) {
            const ProgramBuild build = m_offscreen.useProgram(p.vertexSource(), p.fragmentSource());
            QVERIFY2(build.ok() && build.diagnostics.empty(),
                     qPrintable(p.name + ": " + build.log()));
        }
    }

    void exerciseNamesAndMat3NormalMatrix()
    {
        // aVertex* attributes, uModelViewMatrix, mat3 uNormalMatrix, uLightPosition in camera
        // coordinates and uLightColor (= Id). Diffuse only, so the scene turns the other terms
        // off and the reference is Id * Kd * max(N.L, 0).
        const ProgramBuild build = m_offscreen.useProgram(fixture("exercise_diffuse.vert"),
                                                          fixture("exercise_diffuse.frag"));
        QVERIFY2(build.ok(), qPrintable(build.log()));
        Scene s = testScene();
        s.shading.shading = Shading::Phong;
        s.lights[0].position = {1.5f, 2.0f, 2.5f, 1.0f};
        s.lights[0].colors = {glm::vec3(0.0f), glm::vec3(0.9f, 0.6f, 0.3f), glm::vec3(0.0f)};
        s.objects[0].material.kd = glm::vec3(1.0f);
        // The exercise normalises N per vertex before interpolating; under the non-uniform
        // scale that moves a few pixels by up to 3 levels from the reference, which
        // interpolates the unnormalised normal. (A wrong normal matrix is off by far more.)
        const QString failure =
            checkAgainstReference(m_offscreen, s, "exercise diffuse", 100, 0, 4);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
    }

    void errorsOnTheEditorsLine_data()
    {
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<int>("line");
        // The missing ';' is reported where the parser notices it: the closing brace, the
        // body's line 4, after however many lines come before the body.
        const QString body = "void main()\n{\n    gl_FragColor = vec4(1.0)\n}\n";
        QTest::newRow("webgl 1, no #version") << "precision mediump float;\n" + body << 5;
        QTest::newRow("#version 100") << "#version 100\nprecision mediump float;\n" + body << 6;
        QTest::newRow("#version 300 es")
            << "#version 300 es\nprecision mediump float;\nout vec4 colour;\n"
               "void main()\n{\n    colour = vec4(1.0)\n}\n"
            << 7;
        QTest::newRow("#version 330 core")
            << "#version 330 core\nout vec4 c;\nvoid main()\n{\n    c = vec4(1.0)\n}\n"
            << 6;
    }

    void errorsOnTheEditorsLine()
    {
        QFETCH(QString, fragment);
        QFETCH(int, line);
        // The same line whether WebGL 1 runs under "#version 100" or translated to GLSL 3.30.
        for (const bool translate : {false, true}) {
            setWebGl1TranslationForced(translate);
            const ProgramBuild build = m_offscreen.useProgram(kPlainVertex, fragment);
            setWebGl1TranslationForced(false);
            QVERIFY(!build.ok());
            QVERIFY(!build.diagnostics.empty());
            const Diagnostic &d = build.diagnostics.front();
            QCOMPARE(d.stage, ShaderStage::Fragment);
            QCOMPARE(d.severity, Diagnostic::Severity::Error);
            QVERIFY2(d.line == line, qPrintable(build.log()));
        }
    }

    // Drivers without GLSL ES 1.00 in a core context get WebGL 1 shaders translated to GLSL
    // 3.30; forced here on Mesa, the slides' and the exercise's shaders build without a
    // diagnostic and draw the same pixels both ways. Mesa computes "mediump" at lower
    // precision in GLSL ES (GLSL 3.30 ignores precision), so the pixels compared are those of
    // the source with highp, the same arithmetic; as pasted, the difference is printed.
    void translatedWebGl1DrawsTheSamePixels_data()
    {
        QTest::addColumn<QString>("vertex");
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<int>("shading");
        for (const Preset &p : presets())
            if (p.name.startsWith("Slides"))
                QTest::newRow(qPrintable(p.name))
                    << p.vertexSource() << p.fragmentSource()
                    << int(p.gouraud.value_or(false) ? Shading::Gouraud : Shading::Phong);
        QTest::newRow("the exercise's diffuse")
            << fixture("exercise_diffuse.vert") << fixture("exercise_diffuse.frag")
            << int(Shading::Phong);
        // What the translation rewrites besides: gl_FragData, texture2D, a name that is a
        // word of GLSL 3.30, an #extension line.
        QTest::newRow("texture2D, gl_FragData, a variable named texture")
            << QString(kPlainVertex)
            << "#extension GL_OES_standard_derivatives : enable\nprecision mediump float;\n"
               "uniform sampler2D uTexture;\nvoid main() {\n"
               "  vec4 texture = texture2D(uTexture, gl_FragCoord.xy / 64.0);\n"
               "  gl_FragData[0] = texture + vec4(fwidth(gl_FragCoord.x) * 0.1);\n}\n"
            << int(Shading::Phong);
    }

    void translatedWebGl1DrawsTheSamePixels()
    {
        QFETCH(QString, vertex);
        QFETCH(QString, fragment);
        QFETCH(int, shading);
        Scene s = testScene();
        s.shading.shading = Shading(shading);
        const auto draw = [&](const QString &f, bool translate) {
            setWebGl1TranslationForced(translate);
            const ProgramBuild build = m_offscreen.useProgram(vertex, f);
            setWebGl1TranslationForced(false);
            if (!build.ok() || !build.diagnostics.empty())
                qWarning("%s: %s", translate ? "translated" : "as pasted", qPrintable(build.log()));
            return build.ok() && build.diagnostics.empty() ? m_offscreen.render(s) : QImage();
        };
        QString highp = fragment;
        highp.replace("precision mediump float", "precision highp float");
        const QImage pasted = draw(fragment, false), sameMath = draw(highp, false),
                     translated = draw(fragment, true);
        QVERIFY(!pasted.isNull() && !sameMath.isNull() && !translated.isNull());
        QCOMPARE(translated.size(), sameMath.size());
        // The same arithmetic through one compiler: a level of tolerance at most.
        const int worst = imageDifference(translated, sameMath);
        QVERIFY2(worst <= 1, qPrintable(QString("largest difference %1/255").arg(worst)));
        qInfo("as pasted (mediump in GLSL ES) vs translated: largest difference %d/255",
              imageDifference(pasted, translated));
    }

    void badSourcesKeepTheLastGoodProgram_data()
    {
        QTest::addColumn<QString>("vertex");
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<QString>("expected"); // part of the first message
        const QString v = kPlainVertex, f = kWhiteFragment;
        QByteArray garbage(4096, '\0');
        for (int i = 0; i < garbage.size(); ++i)
            garbage[i] = char((i * 7919 + 13) % 256);
        QTest::newRow("empty") << v << QString() << "empty";
        QTest::newRow("binary garbage") << v << QString::fromLatin1(garbage) << "";
        QTest::newRow("2 MB source") << v << f + QString(2 * 1024 * 1024, ' ') << "KiB";
        QTest::newRow("no main") << v << "precision mediump float;\nvoid other() {}\n"
                                 << "main";
        QTest::newRow("no position input") << "void main() { gl_Position = vec4(0.0); }\n"
                                           << f << "position";
        QTest::newRow("uniform array of 10000")
            << "attribute vec4 vPosition;\nuniform vec4 big[10000];\n"
               "void main() { gl_Position = vPosition + big[int(vPosition.x)]; }\n"
            << f << "";
        QTest::newRow("links but writes nothing")
            << v << "precision mediump float;\nvoid main() {}\n"
            << "writes no colour";
        QTest::newRow("one uniform, two types") << "attribute vec4 vPosition;\nuniform float k;\n"
                                                   "void main() { gl_Position = vPosition * k; }\n"
                                                << "precision mediump float;\nuniform vec3 k;\n"
                                                   "void main() { gl_FragColor = vec4(k, 1.0); }\n"
                                                << "k";
    }

    void badSourcesKeepTheLastGoodProgram()
    {
        QFETCH(QString, vertex);
        QFETCH(QString, fragment);
        QFETCH(QString, expected);
        Scene s = testScene();
        QVERIFY(m_offscreen.useProgram(kPlainVertex, kWhiteFragment).ok());
        const QImage good = m_offscreen.render(s);
        const ProgramBuild bad = m_offscreen.useProgram(vertex, fragment);
        QVERIFY(!bad.ok());
        QVERIFY(bad.hasErrors());
        QVERIFY2(bad.log().contains(expected), qPrintable(bad.log()));
        QCOMPARE(imageDifference(m_offscreen.render(s), good), 0);
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestUserShaders test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_user_shaders.moc"
