// GLSL handled as text: dialect detection and driver logs mapped to the user's lines.
// The Mesa lines are real llvmpipe output; the others are the documented forms.
#include "bindings.h"
#include "diagnostics.h"
#include "dialect.h"
#include "legacy_builtins.h"
#include "loops.h"
#include "presets.h"
#include "unfed_inputs.h"
#include "webgl1_translation.h"

#include <QTest>

using namespace lb;
using Severity = Diagnostic::Severity;

class TestGlslText : public QObject
{
    Q_OBJECT
private slots:
    // Endless loops named on their line; loops that end (or might) left alone.
    void endlessLoops_data()
    {
        QTest::addColumn<QString>("source");
        QTest::addColumn<int>("line"); // 0: no warning
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("words");
        const QString head = "precision mediump float;\nuniform float n;\nvoid main() {\n";
        QTest::newRow("for (;;)") << head + "    float x = 0.0;\n    for (;;) { x += 1.0; }\n}\n"
                                  << 5 << 5 << "no condition";
        QTest::newRow("while (true)") << head + "  while (true) {}\n}\n" << 4 << 3 << "always true";
        QTest::newRow("while ((true))") << head + "  while ((true)) { }\n}\n"
                                        << 4 << 3 << "always true";
        QTest::newRow("do while (true)")
            << head + "  float x;\n  do {\n    x *= 2.0;\n  } while (true);\n}\n"
            << 5 << 3 << "always true";
        QTest::newRow("condition nothing changes")
            << head + "  int i = 0; float s = 0.0;\n  while (i < 10) { s += 1.0; }\n}\n"
            << 5 << 3 << "reads i";
        QTest::newRow("for without a step")
            << head + "  float s = 0.0;\n  for (int i = 0; i < int(n); ) s += 1.0;\n}\n"
            << 5 << 3 << "reads i, n";
        QTest::newRow("a comment and a #define between")
            << head + "#define FOREVER for(;;)\n  /* for (;;) */ // while (true)\n"
                      "  for ( ; ; )\n  {\n  }\n}\n"
            << 6 << 3 << "no condition";
        QTest::newRow("10^9 steps")
            << head + "  float k = 0.0;\n  for (int i = 0; i < 1000000000; i++) { k += 1e-6; }\n}\n"
            << 5 << 3 << "runs 1,000,000,000 times for every fragment";
        QTest::newRow("10^7 steps down, by twos")
            << head + "  for (int i = 20000000; i >= 1; i -= 2) {}\n}\n"
            << 4 << 3 << "runs 10,000,000 times";
        QTest::newRow("a hex bound, <=")
            << head + "  for (uint i = 0u; i <= 0xffffffu; ++i) {}\n}\n"
            << 4 << 3 << "runs 16,777,216 times";
        // (GLSL's int wraps around: 0, -1, ... -2^31, then 2^31 - 1 ends it.)
        QTest::newRow("counted the wrong way")
            << head + "  for (int i = 0; i < 1000000000; i--) {}\n}\n"
            << 4 << 3 << "runs 2,147,483,649 times for every fragment (its counter moves away";
        // Not named:
        QTest::newRow("a million steps") << head + "  for (int i = 0; i < 1000000; i++) {}\n}\n"
                                         << 0 << 0 << "";
        QTest::newRow("long, with a break")
            << head + "  for (int i = 0; i < 1000000000; i++) { if (n > 0.5) break; }\n}\n"
            << 0 << 0 << "";
        QTest::newRow("counted") << head + "  for (int i = 0; i < 4; ++i) {}\n}\n" << 0 << 0 << "";
        QTest::newRow("break") << head + "  for (;;) { if (n > 1.0) break; }\n}\n" << 0 << 0 << "";
        QTest::newRow("discard") << head + "  while (true) { discard; }\n}\n" << 0 << 0 << "";
        QTest::newRow("changed in the body")
            << head + "  float k = n + 2.0;\n  while (k > 0.0) { k = k * 1.0 + 0.0001; }\n}\n"
            << 0 << 0 << "";
        QTest::newRow("member changed")
            << head + "  vec3 v;\n  while (v.x < 1.0) { v.x += 0.5; }\n}\n"
            << 0 << 0 << "";
        QTest::newRow("array element changed")
            << head + "  float a[2];\n  while (a[0] < 1.0) a[0]++;\n}\n"
            << 0 << 0 << "";
        QTest::newRow("changed in the condition")
            << head + "  int i = 0;\n  while (i++ < 10) {}\n}\n"
            << 0 << 0 << "";
        QTest::newRow("a function of the file") << "float g;\nvoid step2() { g += 1.0; }\nvoid "
                                                   "main() {\n  while (g < 4.0) step2();\n}\n"
                                                << 0 << 0 << "";
        QTest::newRow("inside #if 0") << head + "#if 0\n  while (true) {}\n#endif\n}\n"
                                      << 0 << 0 << "";
        QTest::newRow("a macro hides the way out")
            << "#define BREAK_IF(c) if (c) break;\nvoid main() {\n  float t = 0.0;\n"
               "  for (;;) { t += 0.1; BREAK_IF(t > 1.0) }\n}\n"
            << 0 << 0 << "";
        QTest::newRow("nested, the inner one endless")
            << head + "  for (int i = 0; i < 3; ++i) {\n    while (true) { }\n  }\n}\n"
            << 5 << 5 << "always true";
        QTest::newRow("do while that ends")
            << head + "  int i = 0;\n  do { i++; } while (i < 3);\n}\n"
            << 0 << 0 << "";
    }

    void endlessLoops()
    {
        QFETCH(QString, source);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, words);
        const auto d = endlessLoopWarnings(source, ShaderStage::Fragment);
        if (line == 0) {
            QVERIFY2(d.empty(), d.empty() ? "" : qPrintable(d[0].message));
            return;
        }
        QCOMPARE(int(d.size()), 1);
        QCOMPARE(d[0].severity, Severity::Warning);
        QCOMPARE(d[0].line, line);
        QCOMPARE(d[0].column, column);
        QVERIFY2(d[0].message.contains(words), qPrintable(d[0].message));
    }

    // Which vertex stages may run before their trial answers (the viewport's early code
    // generation): only counted loops, and short ones.
    void shortLoops()
    {
        QVERIFY(onlyShortLoops("void main() {}", 64));
        QVERIFY(onlyShortLoops(builtInPreset(true).vertexSource(), 64)); // MAX_LIGHTS = 4
        QVERIFY(onlyShortLoops("#define N 8\nvoid main() { for (int i = 0; i < N; i++) {} }", 8));
        QVERIFY(!onlyShortLoops("#define N 9\nvoid main() { for (int i = 0; i < N; i++) {} }", 8));
        QVERIFY(
            !onlyShortLoops("uniform int n;\nvoid main() { for (int i = 0; i < n; i++) {} }", 64));
        QVERIFY(!onlyShortLoops("void main() { float k = 1.0; while (k > 0.0) k -= 0.1; }", 64));
        QVERIFY(!onlyShortLoops(
            "void main() { for (int i = 0; i < 4; i++) { do {} while (false); } }", 64));
    }

    void noPresetHasAnEndlessLoop()
    {
        for (const Preset &p : presets())
            for (const auto &[stage, text] :
                 {std::pair{ShaderStage::Vertex, p.vertexSource()},
                  std::pair{ShaderStage::Fragment, p.fragmentSource()}}) {
                const auto d = endlessLoopWarnings(text, stage);
                QVERIFY2(d.empty(), qPrintable(p.name + ": " + (d.empty() ? "" : d[0].message)));
            }
    }

    void driverLogs_data()
    {
        QTest::addColumn<QString>("log");
        QTest::addColumn<int>("linesAdded");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<bool>("error");
        QTest::addColumn<QString>("message");
        QTest::newRow("mesa syntax")
            << "0:6(1): error: syntax error, unexpected '}', expecting ',' or ';'" << 0 << 6 << 1
            << true << "syntax error, unexpected '}', expecting ',' or ';'";
        QTest::newRow("mesa behind #version 100")
            << "0:7(1): error: syntax error, unexpected '}', expecting ',' or ';'" << 1 << 6 << 1
            << true << "syntax error, unexpected '}', expecting ',' or ';'";
        QTest::newRow("mesa undeclared")
            << "0:4(40): error: `z' undeclared" << 0 << 4 << 40 << true << "`z' undeclared";
        QTest::newRow("mesa preprocessor")
            << "0:2(77): preprocessor error: syntax error, unexpected HASH_TOKEN" << 1 << 1 << 77
            << true << "syntax error, unexpected HASH_TOKEN";
        QTest::newRow("mesa warning") << "0:3(10): warning: `x' used uninitialized" << 0 << 3 << 10
                                      << false << "`x' used uninitialized";
        QTest::newRow("mesa link") << "error: fragment shader lacks `main'" << 0 << 0 << 0 << true
                                   << "fragment shader lacks `main'";
        QTest::newRow("mesa link, no severity")
            << "Too many vertex shader default uniform block components" << 0 << 0 << 0 << true
            << "Too many vertex shader default uniform block components";
        // Mesa joins a link log's repeated warnings with a "." and ends it with a lone one.
        QTest::newRow("mesa link, joined warnings")
            << "warning: fragment shader varying fPosition not written by vertex shader\n"
               ".warning: fragment shader varying fPosition not written by vertex shader\n."
            << 0 << 0 << 0 << false
            << "fragment shader varying fPosition not written by vertex shader";
        QTest::newRow("nvidia error")
            << "0(12) : error C0000: syntax error, unexpected '}' at token \"}\"" << 0 << 12 << 0
            << true << "syntax error, unexpected '}' at token \"}\"";
        QTest::newRow("nvidia warning behind prefix")
            << "0(8) : warning C7533: global variable gl_FragColor is deprecated" << 1 << 7 << 0
            << false << "global variable gl_FragColor is deprecated";
        QTest::newRow("amd/apple error") << "ERROR: 0:12: 'foo' : undeclared identifier" << 0 << 12
                                         << 0 << true << "'foo' : undeclared identifier";
        QTest::newRow("amd/apple warning") << "WARNING: 0:3: 'extension' : not supported" << 0 << 3
                                           << 0 << false << "'extension' : not supported";
        QTest::newRow("line in the prefix maps to line 1")
            << "0:1(1): error: bad version" << 1 << 1 << 1 << true << "bad version";
    }

    void driverLogs()
    {
        QFETCH(QString, log);
        QFETCH(int, linesAdded);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(bool, error);
        QFETCH(QString, message);
        const auto d = parseDriverLog(log, ShaderStage::Fragment, linesAdded);
        QCOMPARE(int(d.size()), 1); // a repeated message once
        QCOMPARE(d[0].line, line);
        QCOMPARE(d[0].column, column);
        QCOMPARE(d[0].severity == Severity::Error, error);
        QCOMPARE(d[0].message, message);
        QCOMPARE(d[0].stage, ShaderStage::Fragment);
    }

    void multiLineLogsAndNvidiaHeadings()
    {
        const QString log = "Vertex info\n-----------\n0(3) : error C1008: undefined variable "
                            "\"x\"\n\n0(5) : warning C7050: \"y\" might be used before being "
                            "initialized\n";
        const auto d = parseDriverLog(log, ShaderStage::Link);
        QCOMPARE(int(d.size()), 2);
        QCOMPARE(d[0].line, 3);
        QCOMPARE(d[1].line, 5);
        QCOMPARE(d[1].severity, Severity::Warning);
        QVERIFY(parseDriverLog("\n  \n", ShaderStage::Vertex).empty());
    }

    void dialects()
    {
        PreparedSource p = prepareSource("attribute vec4 vPosition;\nvoid main() {}\n");
        QCOMPARE(p.dialect, Dialect::WebGL1Implicit);
        QCOMPARE(p.linesAdded, 1);
        QVERIFY(p.text.startsWith("#version 100\nattribute vec4 vPosition;"));

        p = prepareSource("// a comment\n#version 300 es\nprecision mediump float;\n");
        QCOMPARE(p.dialect, Dialect::Versioned);
        QCOMPARE(p.version, QString("300 es"));
        QCOMPARE(p.linesAdded, 0);
        QCOMPARE(p.text, QString("// a comment\n#version 300 es\nprecision mediump float;\n"));

        p = prepareSource("  #  version   330   core\nvoid main() {}");
        QCOMPARE(p.version, QString("330 core"));

        // A #version inside a comment is no directive.
        p = prepareSource("/* #version 330 core */\n// #version 450\nvoid main() {}");
        QCOMPARE(p.dialect, Dialect::WebGL1Implicit);
    }

    // WebGL 1 as GLSL 3.30 core, line for line (the GL tests draw both; this is the text).
    void webGl1Translation()
    {
        const QString vertex = "// attribute and varying in a comment stay\n"
                               "attribute vec4 vPosition; varying vec2 vUv;\n"
                               "uniform float texture; // a 3.30 word as a name\n"
                               "void main() { vUv = vPosition.xy * texture; "
                               "gl_Position = vPosition; }\n";
        TranslatedSource t = translateWebGl1(vertex, ShaderStage::Vertex);
        QCOMPARE(t.linesAdded, 2);
        QCOMPARE(t.text, QString("#version 330 core\n\n"
                                 "// attribute and varying in a comment stay\n"
                                 "in vec4 vPosition; out vec2 vUv;\n"
                                 "uniform float lb_texture; // a 3.30 word as a name\n"
                                 "void main() { vUv = vPosition.xy * lb_texture; "
                                 "gl_Position = vPosition; }\n"));

        const QString fragment = "#version 100\n"
                                 "#extension GL_OES_standard_derivatives : enable\n"
                                 "precision mediump float;\nvarying vec2 vUv;\n"
                                 "uniform sampler2D s;\n"
                                 "void main() { gl_FragColor = texture2D(s, vUv) * 1e-1; }\n";
        t = translateWebGl1(fragment, ShaderStage::Fragment);
        QCOMPARE(t.text, QString("#version 330 core\nout vec4 lb_FragColor;\n"
                                 "\n\n" // #version 100 and #extension: blank lines
                                 "precision mediump float;\nin vec2 vUv;\n"
                                 "uniform sampler2D s;\n"
                                 "void main() { lb_FragColor = texture(s, vUv) * 1e-1; }\n"));
        // Lines kept: the user's line N is the driver's line N + linesAdded.
        QCOMPARE(t.text.count('\n'), fragment.count('\n') + t.linesAdded);

        // Only WebGL 1 is translated, and only when asked.
        QCOMPARE(prepareSource(fragment, ShaderStage::Fragment, true).dialect,
                 Dialect::WebGL1Translated);
        QCOMPARE(prepareSource(fragment, ShaderStage::Fragment, false).version, QString("100"));
        const QString es3 = "#version 300 es\nprecision mediump float;\nout vec4 c;\n";
        QCOMPARE(prepareSource(es3, ShaderStage::Fragment, true).text, es3);
    }

    // GLSL 1.20's built-ins become names the semantic table feeds, declared in the header's
    // second line; lines stay where they are; a block used whole is left for the driver.
    void legacyTranslation()
    {
        const QString vertex =
            "#version 120\n"
            "varying vec3 n; // gl_Normal in a comment stays\n"
            "void main() { n = gl_NormalMatrix * gl_Normal;\n"
            "  vec4 l = gl_LightSource[ 0 ].position + gl_LightSource[i].halfVector;\n"
            "  gl_FrontColor = gl_BackMaterial.diffuse * l;\n"
            "  gl_Position = ftransform(); }\n";
        TranslatedSource t = translateLegacyGlsl(vertex, ShaderStage::Vertex);
        QCOMPARE(t.linesAdded, 2);
        const QStringList lines = t.text.split('\n');
        QCOMPARE(lines.size(), vertex.count('\n') + 1 + t.linesAdded);
        QCOMPARE(lines[0], QString("#version 330 core"));
        for (const char *declared :
             {"uniform mat3 lb_NormalMatrix;", "layout(location = 1) in vec3 lb_Normal;",
              "uniform vec4 lb_LightSource_position[4];",
              "uniform vec4 lb_LightSource_halfVector[4];", "out vec4 lb_FrontColor;",
              "uniform vec4 lb_FrontMaterial_diffuse;",
              "uniform mat4 lb_ModelViewProjectionMatrix;",
              "layout(location = 0) in vec4 lb_Vertex;"})
            QVERIFY2(lines[1].contains(declared), qPrintable(lines[1]));
        QCOMPARE(lines[2], QString());
        QCOMPARE(lines[3], QString("out vec3 n; // gl_Normal in a comment stays"));
        QCOMPARE(lines[4], QString("void main() { n = lb_NormalMatrix * lb_Normal;"));
        QCOMPARE(lines[5], QString("  vec4 l = lb_LightSource_position[ 0 ] + "
                                   "lb_LightSource_halfVector[i];"));
        QCOMPARE(lines[6], QString("  lb_FrontColor = lb_FrontMaterial_diffuse * l;"));
        QCOMPARE(lines[7],
                 QString("  gl_Position = (lb_ModelViewProjectionMatrix * lb_Vertex); }"));

        // The fragment's gl_Color is what the vertex stage wrote; a block passed whole, or a
        // member the pipeline never had, stays for the driver to name.
        t = translateLegacyGlsl("void main() { gl_FragColor = gl_Color + f(gl_LightSource[0]) + "
                                "gl_FrontMaterial.glow; }\n",
                                ShaderStage::Fragment);
        QVERIFY2(t.text.contains("in vec4 lb_FrontColor;") &&
                     t.text.contains("lb_FragColor = lb_FrontColor + f(gl_LightSource[0]) + "
                                     "gl_FrontMaterial.glow;"),
                 qPrintable(t.text));
        QCOMPARE(withLegacyNames("'lb_LightSource_position' undeclared; lb_Vertex, lb_FrontColor, "
                                 "lb_FrontMaterial_diffuse"),
                 QString("'gl_LightSource[].position' undeclared; gl_Vertex, gl_FrontColor, "
                         "gl_FrontMaterial.diffuse"));

        // A hostile run of unclosed indices is left as written, each read no further than an
        // index can be long (it scanned the rest of the line each time: 1 MB took the 15 s trial).
        const QString unclosed = QString("gl_LightSource[").repeated(20000);
        t = translateLegacyGlsl("void main() { vec4 a = " + unclosed + "\n}\n",
                                ShaderStage::Vertex);
        QVERIFY(t.text.contains(unclosed));

        // A program of that era: either stage uses a built-in, neither says a later version.
        const QString plain = "void main() { gl_FragColor = vec4(1.0); }\n";
        QVERIFY(legacyProgram(vertex, plain));
        QVERIFY(legacyProgram("void main() { gl_Position = ftransform(); }", plain));
        QVERIFY(!legacyProgram("attribute vec4 p; void main() { gl_Position = p; }", plain));
        QVERIFY(
            !legacyProgram("#version 330 core\nvoid main() { gl_Position = gl_Vertex; }", plain));
        QVERIFY(!legacyProgram("// gl_Vertex\nattribute vec4 p; void main() { gl_Position = p; }",
                               plain));
    }

    void fragmentOutputs()
    {
        QVERIFY(writesFragmentColour("void main() { gl_FragColor = vec4(1.0); }"));
        QVERIFY(writesFragmentColour("void main() { gl_FragData[0] = vec4(1.0); }"));
        QVERIFY(writesFragmentColour("#version 330 core\nout vec4 colour;\nvoid main() {}"));
        QVERIFY(writesFragmentColour("layout(location = 0) out vec4 c;\nvoid main() {}"));
        QVERIFY(!writesFragmentColour("precision mediump float;\nvoid main() { }"));
        QVERIFY(!writesFragmentColour("void main() { /* gl_FragColor = vec4(1.0); */ }"));
    }

    // A matrix nothing feeds is named on its declaration's line, in the stage that declares
    // it, with the names the scene feeds; a fed one, or a vector (it gets a control), is not.
    void unfedMatricesAreNamedOnTheirLine()
    {
        const auto uniform = [](const QString &name, UniformKind kind, int width) {
            ActiveUniform u;
            u.name = name;
            u.kind = kind;
            u.width = width;
            u.semantic = semanticOf(name, shapeOf(kind));
            return u;
        };
        const QString vertex = "attribute vec4 p;\n"
                               "// uniform mat4 uWorldToClip; (a comment is no declaration)\n"
                               "uniform mat4 model;\n"
                               "uniform   mat4 uWorldToClip;\n"
                               "void main() { gl_Position = uWorldToClip * model * p; }\n";
        const QString fragment = "precision mediump float;\nuniform vec3 tint;\n"
                                 "uniform mat3 uColourMix;\n"
                                 "uniform vec3 uLightPos, uEyePos, uMine;\n"
                                 "uniform float bands;\n"
                                 "uniform vec3 uSunColour;\n"
                                 "void main() { gl_FragColor = vec4(uColourMix * tint, 1.0); }\n";
        std::vector<ActiveUniform> uniforms = {
            uniform("model", UniformKind::Matrix, 4),
            uniform("uWorldToClip", UniformKind::Matrix, 4),
            uniform("tint", UniformKind::Float, 3),
            uniform("uColourMix", UniformKind::Matrix, 3),
            uniform("uLightPos", UniformKind::Float, 3),
            uniform("uEyePos", UniformKind::Float, 3),
            uniform("uMine", UniformKind::Float, 3), // bound to none below: its own value
            uniform("bands", UniformKind::Float, 1),
            uniform("uSunColour", UniformKind::Float, 3), // initialised to white below
        };
        for (ActiveUniform &u : uniforms)
            u.initial.assign(std::size_t(u.width), 0.0f);
        uniforms.back().initial = {1.0f, 1.0f, 1.0f};
        const std::vector<Diagnostic> notApplied =
            applyBindings(uniforms, {{"uMine", std::nullopt}, {"tint", Semantic::Projection}});
        QCOMPARE(notApplied.size(), std::size_t(1)); // a vec3 takes no matrix
        QVERIFY2(notApplied[0].message.contains("tint=projection"),
                 qPrintable(notApplied[0].message));
        QVERIFY(uniforms[0].semantic); // LearnOpenGL's
        const std::vector<Diagnostic> warnings = unfedInputWarnings(uniforms, vertex, fragment);
        QCOMPARE(warnings.size(), std::size_t(4));
        QCOMPARE(warnings[0].severity, Diagnostic::Severity::Warning);
        QCOMPARE(warnings[0].stage, ShaderStage::Vertex);
        QCOMPARE(warnings[0].line, 4);
        QVERIFY(warnings[0].message.contains("uWorldToClip"));
        // Nothing in its name says which: every matrix the scene gives.
        for (const char *fed : {"model-view,", "model,", "projection,", "model-view-projection"})
            QVERIFY2(warnings[0].message.contains(fed), qPrintable(warnings[0].message));
        QCOMPARE(warnings[1].stage, ShaderStage::Fragment);
        QCOMPARE(warnings[1].line, 3);
        QVERIFY(warnings[1].message.contains("uColourMix"));
        // What the names say comes first.
        QCOMPARE(warnings[2].line, 4);
        QVERIFY2(warnings[2].message.contains("uLightPos") &&
                     warnings[2].message.contains(
                         "one of light-position, light-position-camera, light-position-world"),
                 qPrintable(warnings[2].message));
        QVERIFY2(warnings[3].message.contains("--bind uEyePos=KEY") &&
                     warnings[3].message.contains("one of camera-position-world"),
                 qPrintable(warnings[3].message));
    }

    // Each semantic has one key and one label; keys read back; the names' words find them.
    void bindingKeys()
    {
        QStringList keys = semanticKeys();
        QCOMPARE(keys.size(), int(kLastSemantic) + 1);
        for (int i = 0; i <= int(kLastSemantic); ++i) {
            const Semantic s = Semantic(i);
            QCOMPARE(semanticFromKey(semanticKey(s)), std::optional<Semantic>(s));
            QVERIFY(!semanticLabel(s).isEmpty());
        }
        keys.removeDuplicates();
        QCOMPARE(keys.size(), int(kLastSemantic) + 1);
        bool unbound = false;
        QVERIFY(!semanticFromKey("none", &unbound) && unbound);
        QVERIFY(!semanticFromKey("model-veiw", &unbound) && !unbound);
        const auto suggested = [](const char *name, UniformShape shape) {
            QStringList found;
            for (Semantic s : suggestedSemantics(name, shape))
                found << semanticKey(s);
            return found.join(' ');
        };
        QCOMPARE(suggested("uMVP", UniformShape::Matrix), QString("model-view-projection"));
        QCOMPARE(suggested("u_objectColor", UniformShape::Number), QString("material-diffuse"));
        QCOMPARE(suggested("uColor", UniformShape::Number),
                 QString("light-diffuse material-diffuse diffuse-product"));
        QCOMPARE(suggested("uEnableSpecularTerm", UniformShape::Number),
                 QString("enable-specular"));
        QCOMPARE(suggested("materialKd", UniformShape::Number), QString("material-diffuse"));
        QCOMPARE(suggested("u_lightDir", UniformShape::Number),
                 QString("light-direction-world reverse-light-direction"));
        QCOMPARE(suggested("bands", UniformShape::Number), QString());
    }
};

QTEST_APPLESS_MAIN(TestGlslText)
#include "test_glsl_text.moc"
