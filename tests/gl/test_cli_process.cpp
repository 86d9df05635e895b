// The lightbench executable as a user scripts it: exit codes, messages, PNG and probe JSON.
#include "frames.h"
#include "platform_skips.h"
#include "reference_compare.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cstdlib>

#include <sys/stat.h>

namespace {
struct Run
{
    int exitCode;
    QByteArray out, err;
};

// Writes `bytes` to `path`; false when it cannot.
bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

// A fragment shader with no loop whose `lines` lines of sin() all run in every pixel (they
// read a varying: nothing folds them away).
QByteArray heavyFragment(int lines)
{
    QByteArray text =
        "precision mediump float;\nvarying vec3 v;\nvoid main() {\n  vec3 c = v * 0.1;\n";
    for (int i = 0; i < lines; ++i)
        text +=
            QString("  c += sin(c * %1.01 + vec3(%2.0));\n").arg(i % 7 + 1).arg(i % 13).toUtf8();
    return text + "  gl_FragColor = vec4(c, 1.0);\n}\n";
}

Run run(const QStringList &args,
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(LIGHTBENCH_EXE, args);
    if (!p.waitForFinished(60000))
        return {-1, {}, "timed out"};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError()};
}
} // namespace

class TestCliProcess : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void renderWritesAnImageOfTheGivenSize()
    {
        const QString png = m_dir.filePath("frame.png");
        const Run r = run({"--render", png, "--size", "200x150", "--shape", "torus"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage img(png);
        QCOMPARE(img.size(), QSize(200, 150));
        QVERIFY(img.pixel(100, 75) != img.pixel(2, 2)); // the torus is there, not background
    }

    void probePrintsTheModelAtThePixel()
    {
        const Run r = run({"--probe", "400,300", "--shading", "gouraud", "--show-light", "off"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY(o["hit"].toBool());
        for (const char *key :
             {"gpu", "reference", "position", "normal", "V", "ambient", "diffuse", "specular"})
            QVERIFY2(o[key].isArray() && o[key].toArray().size() == 3, key);
        // One light by default; its vectors and terms are listed under "lights".
        QCOMPARE(o["lights"].toArray().size(), 1);
        const QJsonObject light = o["lights"][0].toObject();
        QCOMPARE(light["light"].toInt(), 1);
        for (const char *key : {"L", "H", "R", "ambient", "diffuse", "specular"})
            QVERIFY2(light[key].isArray() && light[key].toArray().size() == 3, key);
        QCOMPARE(light["specular"], o["specular"]);
        for (int c = 0; c < 3; ++c)
            QVERIFY(std::abs(o["gpu"][c].toInt() - o["reference"][c].toInt()) <= 2);
        // The background has no surface.
        const Run miss = run({"--probe", "2,2"});
        QCOMPARE(QJsonDocument::fromJson(miss.out).object()["hit"].toBool(true), false);
    }

    // The probe reads the surface, not the light's marker drawn over it: a point light in the
    // camera frame between the eye and the sphere sits on the middle pixel (the frame shows
    // the marker there), and the probe still agrees with the reference.
    void probeReadsTheSurfaceUnderTheMarker()
    {
        const QString png = m_dir.filePath("marker.png");
        const Run r = run({"--probe", "100,75", "--size", "200x150", "--frame", "camera", "--light",
                           "0,0,-2.5,1", "--kd", "0,0.4,0", "--ks", "0,0,0", "--render",
                           png}); // a dark green surface under a white marker
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY(o["hit"].toBool());
        QVERIFY2(o["maxDifference"].toInt() <= 2, r.out.constData());
        const QRgb shown = QImage(png).pixel(100, 75);
        QVERIFY2(std::abs(qBlue(shown) - o["gpu"][2].toInt()) > 100, "no marker over the pixel");
    }

    // --object twice: the probe names the object it hits, 0 for the first.
    void probeNamesTheObjectHit()
    {
        using namespace lb;
        Scene s;
        s.objects = {ObjectSettings{}, ObjectSettings{}};
        s.objects[0].shape = Shape::Cube;
        placeInRow(s.objects);
        frameScene(s);
        for (int i = 0; i < 2; ++i) {
            const Frames f = computeFrames(s, 800.0f / 600.0f, i);
            const glm::vec2 p = pixelOf(f, glm::vec3(f.modelView[3]), 800.0f, 600.0f);
            const QString pixel = QString("%1,%2").arg(int(p.x)).arg(int(p.y));
            const Run r = run({"--object", "cube", "--object", "sphere", "--probe", pixel,
                               "--show-light", "off"});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            const QJsonObject o = QJsonDocument::fromJson(r.out).object();
            QVERIFY(o["hit"].toBool());
            QCOMPARE(o["object"].toInt(-1), i);
            QVERIFY(o["maxDifference"].toInt(99) <= 2);
        }
    }

    // Issue 28: what lightbench writes for machines uses a point whatever the locale: the
    // probe's JSON and a saved scene are the same bytes under German or Portuguese as under
    // C (Qt reads LANG itself, though only C and POSIX are installed here).
    void machineOutputIsTheSameInEveryLocale_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::newRow("de_DE") << "de_DE.UTF-8";
        QTest::newRow("pt_PT") << "pt_PT.UTF-8";
    }
    void machineOutputIsTheSameInEveryLocale()
    {
        QFETCH(QString, locale);
        const auto in = [](const QString &name) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove("LC_NUMERIC");
            env.insert("LC_ALL", name);
            env.insert("LANG", name);
            return env;
        };
        const QStringList probe{"--probe",      "400,300", "--light", "0.5,1.8,1.3,1",
                                "--shininess",  "12.5",    "--kd",    "0.25,0.5,0.75",
                                "--show-light", "off"};
        const Run c = run(probe, in("C")), local = run(probe, in(locale));
        QVERIFY2(c.exitCode == 0 && local.exitCode == 0, local.err.constData());
        QCOMPARE(local.out, c.out);
        QVERIFY(QJsonDocument::fromJson(local.out).object()["hit"].toBool());
        QVERIFY2(QRegularExpression("\\d\\.\\d").match(QString(local.out)).hasMatch(),
                 local.out.constData());

        const QString cScene = m_dir.filePath("c.json"), localScene = m_dir.filePath("local.json");
        const QStringList options{"--light", "0.5,1.8,1.3,1", "--shininess",
                                  "12.5",    "--kd",          "0.25,0.5,0.75"};
        QCOMPARE(run(QStringList{"--save-scene", cScene} + options, in("C")).exitCode, 0);
        QCOMPARE(run(QStringList{"--save-scene", localScene} + options, in(locale)).exitCode, 0);
        QFile a(cScene), b(localScene);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray saved = b.readAll();
        QCOMPARE(saved, a.readAll());
        QVERIFY2(saved.contains("12.5"), saved.constData());
    }

    // --probe's JSON and --help on a stdout that was closed (`>&-`) or is full: exit 1 with
    // the reason, not exit 0 with the result gone.
    void resultsOnAClosedOrFullStandardOutputFail_data()
    {
        QTest::addColumn<QString>("redirect");
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        const QStringList probe{"--probe", "50,50", "--size", "100x100"};
        QTest::newRow("probe, closed") << ">&-" << probe << "standard output is closed";
        QTest::newRow("probe, full")
            << ">/dev/full" << probe << "could not write to standard output";
        QTest::newRow("help, closed")
            << ">&-" << QStringList{"--help"} << "standard output is closed";
        QTest::newRow("bench frames, closed")
            << ">&-" << QStringList{"--bench-frames", "2", "--size", "64x64"}
            << "standard output is closed";
    }

    void resultsOnAClosedOrFullStandardOutputFail()
    {
        QFETCH(QString, redirect);
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        if (redirect == ">&-")
            LB_SKIP_WITHOUT_STANDARD_STREAMS();
        QProcess p;
        p.start("/bin/sh",
                QStringList{"-c", "exec \"$0\" \"$@\" " + redirect, LIGHTBENCH_EXE} + args);
        QVERIFY(p.waitForFinished(60000));
        const QByteArray err = p.readAllStandardError();
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(err.contains(said.toUtf8()), err.constData());
    }

    // A file name with %N in it is printed as it is: the messages' chained arg() took a
    // name's "%4" for the next argument (`--check` on %4%5%6.frag printed "errorsyntax
    // error..."; a lesson L%2.json was called L1.json).
    void fileNamesWithPercentSignsArePrintedAsTheyAre()
    {
        const QString vert = m_dir.filePath("%1v.vert"), frag = m_dir.filePath("%4%5%6.frag");
        QVERIFY(writeFile(vert,
                          "attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n"));
        QVERIFY(writeFile(frag, "void main() { gl_FragColor = vec4(1.0) }\n"));
        const Run check = run({"--check", "--vertex", vert, "--fragment", frag});
        QVERIFY2(check.out.contains("%4%5%6.frag:1:") && check.out.contains(": error: "),
                 check.out.constData());
        const QString lesson = m_dir.filePath("L%2.json");
        QVERIFY(writeFile(lesson, R"({"format": "lightbench-lesson", "version": 1,
            "steps": [{"title": "one", "scene": {"unknownField%3": 1}}]})"));
        const Run step =
            run({"--lesson", lesson, "--step", "1", "--render", m_dir.filePath("l.png")});
        QVERIFY2(step.err.contains("L%2.json (step 1)"), step.err.constData());
    }

    // The window ended by SIGTERM (a logout, `kill`) quits as a close with nobody to ask
    // (issue 49): the settings are saved and the settings' scratch folder is gone; it used to
    // end where it stood, saving nothing and leaving lightbench-settings-XXXXXX in TMPDIR.
    void aWindowEndedBySigtermSavesAndCleansUp()
    {
        QTemporaryDir home, tmp;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("HOME", home.path());
        env.insert("XDG_CONFIG_HOME", home.filePath(".config"));
        env.insert("TMPDIR", tmp.path());
        QProcess window;
        window.setProcessEnvironment(env);
        window.start(LIGHTBENCH_EXE, {});
        const QDir scratch(tmp.path());
        QTRY_VERIFY_WITH_TIMEOUT(
            !scratch.entryList({"lightbench-settings-*"}, QDir::Dirs).isEmpty(), 30000);
        QTest::qWait(2000); // shown, its first frame drawn
        window.terminate(); // SIGTERM
        QVERIFY(window.waitForFinished(30000));
        QCOMPARE(window.exitStatus(), QProcess::NormalExit);
        QCOMPARE(window.exitCode(), 143);
        QVERIFY2(scratch.entryList({"lightbench-settings-*"}, QDir::Dirs).isEmpty(),
                 qPrintable(scratch.entryList(QDir::AllEntries | QDir::NoDotAndDotDot).join(", ")));
        QVERIFY(QFileInfo::exists(home.filePath(".config/lightbench/lightbench.conf")));
    }

    void savedSceneRendersTheSameFrame()
    {
        // Options -> --save-scene -> --scene: the same picture, the program included.
        const QString scene = m_dir.filePath("lesson.json");
        const QString data = LB_TEST_DATA;
        const QStringList options{"--shape",        "torus",
                                  "--shading",      "gouraud",
                                  "--light",        "1,2,3,1",
                                  "--kd",           "0.2,0.6,0.9",
                                  "--camera-orbit", "30,20",
                                  "--vertex",       data + "/exercise_diffuse.vert",
                                  "--fragment",     data + "/exercise_diffuse.frag",
                                  "--size",         "200x150"};
        const Run saved = run(QStringList{"--save-scene", scene} + options);
        QVERIFY2(saved.exitCode == 0, saved.err.constData());
        const QString direct = m_dir.filePath("direct.png"), fromFile = m_dir.filePath("file.png");
        QCOMPARE(run(QStringList{"--render", direct} + options).exitCode, 0);
        const Run r = run({"--scene", scene, "--render", fromFile, "--size", "200x150"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(!r.err.contains("ignored"));
        const QImage a(direct), b(fromFile);
        QCOMPARE(a.size(), b.size());
        const int worst = lb::test::largestDifference(a, b);
        QVERIFY2(worst <= 1, qPrintable(QString("%1/255 apart").arg(worst)));
        // Options after the scene override it.
        const QString other = m_dir.filePath("other.png");
        QCOMPARE(run({"--scene", scene, "--render", other, "--size", "200x150", "--shape", "cube"})
                     .exitCode,
                 0);
        QVERIFY(QImage(other) != b);
    }

    // A program of names no convention has draws nothing, and says so on stderr, with each
    // matrix named; --bind feeds them, --save-scene keeps the bindings, and the scene file
    // draws the same lit frame.
    void bindingsFeedAnyNameAndAreSaved()
    {
        QFile v(m_dir.filePath("mine.vert")), f(m_dir.filePath("mine.frag"));
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write("attribute vec3 inPos;\nattribute vec3 inNormal;\nvarying vec3 n;\n"
                "uniform mat4 uToClip;\nuniform mat3 uTurnNormals;\n"
                "void main() { n = uTurnNormals * inNormal; gl_Position = uToClip * "
                "vec4(inPos, 1.0); }\n");
        f.write("precision mediump float;\nvarying vec3 n;\nuniform vec3 uSunDir;\n"
                "uniform vec3 uTint;\nvoid main() {\n"
                "  gl_FragColor = vec4(uTint * max(dot(normalize(n), uSunDir), 0.0), 1.0);\n}\n");
        v.close();
        f.close();
        const QStringList program{"--vertex",   v.fileName(), "--fragment",
                                  f.fileName(), "--size",     "160x120"};
        const QString blank = m_dir.filePath("blank.png");
        const Run unbound = run(QStringList{"--render", blank} + program);
        QCOMPARE(unbound.exitCode, 0);
        for (const char *said :
             {"mine.vert:4:0: warning", "uToClip", "mine.vert:5:0: warning", "draws nothing"})
            QVERIFY2(unbound.err.contains(said), unbound.err.constData());

        const QStringList bindings{"--bind",       "uToClip=model-view-projection",
                                   "--bind",       "uTurnNormals=normal-matrix",
                                   "--bind",       "uSunDir=light-position",
                                   "--bind",       "uTint=material-diffuse",
                                   "--light",      "0,0,1,0",
                                   "--frame",      "camera",
                                   "--kd",         "1,0.5,0.25",
                                   "--show-light", "off"};
        const QString scene = m_dir.filePath("bound.json"), lit = m_dir.filePath("lit.png"),
                      fromFile = m_dir.filePath("lit-file.png");
        const Run bound = run(QStringList{"--render", lit} + program + bindings);
        QVERIFY2(bound.exitCode == 0 && bound.err.isEmpty(), bound.err.constData());
        const QImage image(lit);
        // Head-on light on the sphere's middle: Kd itself.
        const QRgb centre = image.pixel(80, 60);
        QVERIFY2(qRed(centre) > 240 && std::abs(qGreen(centre) - 128) < 8 &&
                     std::abs(qBlue(centre) - 64) < 8,
                 qPrintable(QString::number(centre, 16)));
        QCOMPARE(run(QStringList{"--save-scene", scene} + program + bindings).exitCode, 0);
        QFile saved(scene);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll().contains("\"uToClip\": \"model-view-projection\""));
        const Run again = run({"--scene", scene, "--render", fromFile, "--size", "160x120"});
        QVERIFY2(again.exitCode == 0 && again.err.isEmpty(), again.err.constData());
        QVERIFY(lb::test::largestDifference(image, QImage(fromFile)) <= 1);
    }

    void badSceneFilesAreRefusedOrReadInPart()
    {
        const QString notJson = m_dir.filePath("notes.json");
        QVERIFY(writeFile(notJson, "these are my notes, not a scene"));
        Run r = run({"--scene", notJson, "--render", m_dir.filePath("x.png")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--scene: " + notJson.toUtf8() + ": not a scene file"),
                 r.err.constData());
        r = run({"--scene", "/nowhere/scene.json"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("/nowhere/scene.json: no such file"));

        const QString odd = m_dir.filePath("odd.json");
        QVERIFY(writeFile(odd, R"({"version": 9, "material": {"shininess": "shiny",
                                  "kd": [0, 0, 1]}, "sparkles": 3})"));
        const QString png = m_dir.filePath("odd.png");
        r = run({"--scene", odd, "--render", png, "--size", "200x150"});
        QCOMPARE(r.exitCode, 0);
        QByteArray line; // one line lists everything ignored
        for (const QByteArray &l : r.err.split('\n'))
            if (l.contains("ignored"))
                line = line.isEmpty() ? l : "more than one line";
        QVERIFY2(line.startsWith("lightbench: " + odd.toUtf8() + ": ignored: version 9"),
                 r.err.constData());
        QVERIFY(line.contains("material.shininess (not a number)"));
        QVERIFY(line.contains("sparkles (unknown field)"));
        const QRgb centre = QImage(png).pixel(100, 75);
        QVERIFY(qBlue(centre) > qRed(centre)); // kd was read
    }

    void differenceRenderPrintsTheLargestDifference()
    {
        const QString scene = m_dir.filePath("diff.json");
        QVERIFY(run({"--save-scene", scene, "--show-light", "off"}).exitCode == 0);
        QFile f(scene);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject json = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonObject compare = json["compare"].toObject();
        compare["mode"] = "difference";
        compare["shading"] = "gouraud";
        json["compare"] = compare;
        QVERIFY(writeFile(scene, QJsonDocument(json).toJson()));
        const Run r = run({"--scene", scene, "--render", m_dir.filePath("diff.png")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(o["largestDifference"].toInt() >= 20, r.out.constData());
        const Run same =
            run({"--scene", scene, "--render", m_dir.filePath("same.png"), "--shading", "gouraud"});
        QCOMPARE(QJsonDocument::fromJson(same.out).object()["largestDifference"].toInt(-1), 0);
    }

    void badValuesExitWithCode2AndOneLine_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("option");
        QTest::newRow("w = 0.5") << QStringList{"--light", "1,2,3,0.5"} << "--light";
        QTest::newRow("missing number") << QStringList{"--ka", "1,0"} << "--ka";
        QTest::newRow("nan") << QStringList{"--shininess", "nan"} << "--shininess";
        QTest::newRow("unknown word") << QStringList{"--shape", "teapot"} << "--shape";
        QTest::newRow("size 0") << QStringList{"--size", "0x0"} << "--size";
        QTest::newRow("size 100000") << QStringList{"--size", "100000x10"} << "--size";
        QTest::newRow("unknown option") << QStringList{"--frobnicate"} << "frobnicate";
        QTest::newRow("crease 200") << QStringList{"--crease-angle", "200"} << "--crease-angle";
        QTest::newRow("normals word") << QStringList{"--normals", "wobbly"} << "--normals";
        QTest::newRow("mesh and shape")
            << QStringList{"--mesh", "a.obj", "--shape", "cube"} << "--shape";
        QTest::newRow("memory 0") << QStringList{"--import-memory-limit", "0"}
                                  << "--import-memory-limit";
        QTest::newRow("bind without =") << QStringList{"--bind", "uLamp"} << "--bind";
        QTest::newRow("bind to a typo") << QStringList{"--bind", "uLamp=light-postion"} << "--bind";
        QTest::newRow("bind no name") << QStringList{"--bind", "=model"} << "--bind";
    }

    // Every program is timed before its frame, loops or not: 25,000 lines of sin() without a
    // loop passed --check and then took 4 minutes to render.
    void aProgramWithoutLoopsIsTimedToo()
    {
        const QString vertex = m_dir.filePath("heavy.vert"),
                      fragment = m_dir.filePath("heavy.frag");
        QVERIFY(writeFile(vertex, "attribute vec4 vPosition;\nvarying vec3 v;\n"
                                  "void main() { v = vPosition.xyz; gl_Position = vPosition; }\n"));
        QVERIFY(writeFile(fragment, heavyFragment(60)));
        const Run r = run({"--check", "--size", "1920x1080", "--frame-budget", "0.01", "--vertex",
                           vertex, "--fragment", fragment});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("heavy.frag:0:0: error: drawing one frame with this program "
                                "at 1920x1080 would take more than") &&
                     r.out.contains("too much work for every pixel?"),
                 r.out.constData());
        // The same program within its budget at a small size passes.
        QCOMPARE(run({"--check", "--size", "64x64", "--vertex", vertex, "--fragment", fragment})
                     .exitCode,
                 0);
    }

    // The driver compiles a stranger's program under a memory bound (a 946-byte shader of
    // doubling macros once took its preprocessor to 24 GB): past it, the process ends with a
    // message on the program, not with the machine's memory. The bound is lowered here so
    // that an ordinary compile passes it.
    void aProgramThatTakesTheDriverTooMuchMemoryIsRefused()
    {
        LB_SKIP_WITHOUT_MEMORY_BOUNDS();
        const QString vertex = m_dir.filePath("big.vert"), fragment = m_dir.filePath("big.frag");
        QVERIFY(writeFile(vertex, "attribute vec4 vPosition;\nvarying vec3 v;\n"
                                  "void main() { v = vPosition.xyz; gl_Position = vPosition; }\n"));
        QVERIFY(writeFile(fragment, heavyFragment(300)));
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIGHTBENCH_PROGRAM_MEMORY_MB", "1");
        env.insert("MESA_SHADER_CACHE_DISABLE", "true"); // a cached program takes nothing
        QElapsedTimer clock;
        clock.start();
        const Run r = run({"--check", "--vertex", vertex, "--fragment", fragment}, env);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("big.frag:0:0: error: the driver ran out of memory compiling or "
                                "drawing this program (limit "),
                 r.out.constData());
        QVERIFY(clock.elapsed() < 20000);
    }

    void meshFileRendersAndProbes()
    {
        const QString png = m_dir.filePath("mesh.png");
        const Run r = run({"--mesh", "/usr/share/assimp/models/PLY/cube.ply", "--render", png,
                           "--size", "200x150", "--probe", "100,75", "--show-light", "off"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(QImage(png).size(), QSize(200, 150));
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY(o["hit"].toBool());
        QVERIFY(o["maxDifference"].toInt() <= 2);
    }

    // An image as the texture: drawn (not the checker), its level of detail in the probe's
    // JSON; a missing or broken one exits 1 naming the file.
    void textureFileRendersAndProbes()
    {
        // Green, with stripes and a gradient: the filters and levels read differ.
        QImage image(256, 256, QImage::Format_RGB32);
        for (int y = 0; y < 256; ++y)
            for (int x = 0; x < 256; ++x)
                image.setPixel(x, y, qRgb(x / 4, (x / 3 + y / 5) % 2 ? 230 : 120, 60));
        const QString green = m_dir.filePath("green.png");
        QVERIFY(image.save(green));
        const QString png = m_dir.filePath("textured.png");
        const QStringList scene = {
            "--shape",           "cube", "--show-light", "off",   "--size", "200x150",
            "--texture-mipmaps", "on",   "--kd",         "1,1,1", "--ka",   "1,1,1"};
        Run r = run(scene + QStringList{"--texture-file", green, "--render", png});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QRgb middle = QImage(png).pixel(100, 75);
        QVERIFY2(qGreen(middle) > 2 * qRed(middle), qPrintable(QString::number(middle, 16)));
        for (const char *pixel : {"100,75", "83,61", "117,92"}) {
            r = run(scene + QStringList{"--texture-file", green, "--probe", pixel});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            const QJsonObject probe = QJsonDocument::fromJson(r.out).object();
            QCOMPARE(probe["uv"].toArray().size(), 2);
            // 256 texels across a face about 60 pixels wide: minified by about two levels.
            const double lod = probe["levelOfDetail"].toDouble();
            QVERIFY2(lod > 1.0 && lod < 3.5, qPrintable(QString::number(lod)));
            QVERIFY2(probe["maxDifference"].toInt() <= 3, r.out.constData()); // trilinear
        }

        for (const QString &bad : {m_dir.filePath("none.png"), m_dir.filePath("not.png")}) {
            if (bad.endsWith("not.png"))
                QVERIFY(writeFile(bad, "this is no image"));
            r = run(scene + QStringList{"--texture-file", bad, "--render", png});
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(QFileInfo(bad).fileName().toUtf8()), r.err.constData());
            QCOMPARE(r.err.count("lightbench: "), 1); // one message (Qt may warn besides)
        }
    }

    void meshThatCannotLoadExitsWithOne_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString models = "/usr/share/assimp/models/";
        QTest::newRow("missing") << QStringList{"--mesh", "/nowhere/teapot.obj"}
                                 << "/nowhere/teapot.obj: no such file";
        QTest::newRow("350 billion vertices")
            << QStringList{"--mesh", models + "invalid/OutOfMemory.off", "--import-memory-limit",
                           "300"}
            << "out of memory: reading this file needs more than the import memory limit (300 MB)";
        QTest::newRow("malformed") << QStringList{"--mesh", models + "invalid/malformed.obj"}
                                   << "malformed.obj: OBJ: Invalid face index.";
    }

    void meshThatCannotLoadExitsWithOne()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        if (message.startsWith("out of memory"))
            LB_SKIP_WITHOUT_MEMORY_BOUNDS();
        const QString png = m_dir.filePath("never.png");
        const Run r = run(args + QStringList{"--render", png});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
        QVERIFY(!QFile::exists(png));
    }

    void badValuesExitWithCode2AndOneLine()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, option);
        const QString png = m_dir.filePath("never.png");
        const Run r = run(args + QStringList{"--render", png});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(r.err.contains(option.toUtf8()), r.err.constData());
        QVERIFY(!QFile::exists(png));
    }

    void noDisplayIsAMessageNotACrash()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        const Run r = run({"--render", m_dir.filePath("x.png")}, env);
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("display"));
    }

    void checkPrintsFileLineColumn()
    {
        const QString vert = m_dir.filePath("ok.vert"), frag = m_dir.filePath("bad.frag");
        QFile v(vert), f(frag);
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write("attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n");
        f.write("precision mediump float;\nvoid main() {\n  gl_FragColor = vec4(undeclared);\n}\n");
        v.close();
        f.close();
        const Run bad = run({"--check", "--vertex", vert, "--fragment", frag});
        QCOMPARE(bad.exitCode, 1);
        QVERIFY2(bad.out.startsWith((frag + ":3:").toUtf8()), bad.out.constData());
        QVERIFY(bad.out.contains(": error: "));
        // Translated to GLSL 3.30 (drivers without "#version 100"): the same line.
        const Run translated =
            run({"--check", "--translate-webgl1", "--vertex", vert, "--fragment", frag});
        QCOMPARE(translated.exitCode, 1);
        QVERIFY2(translated.out.startsWith((frag + ":3:").toUtf8()), translated.out.constData());
        // The same program for --render: no image, the diagnostics on stderr, exit 1.
        const QString png = m_dir.filePath("user.png");
        const Run render = run({"--render", png, "--vertex", vert, "--fragment", frag});
        QCOMPARE(render.exitCode, 1);
        QVERIFY(render.err.contains((frag + ":3:").toUtf8()));
        QVERIFY(!QFile::exists(png));

        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("precision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n");
        f.close();
        const Run good = run({"--check", "--vertex", vert, "--fragment", frag});
        QCOMPARE(good.exitCode, 0);
        QVERIFY2(good.out.isEmpty(), good.out.constData());
        QCOMPARE(
            run({"--check", "--translate-webgl1", "--vertex", vert, "--fragment", frag}).exitCode,
            0);
        QCOMPARE(run({"--render", png, "--vertex", vert, "--fragment", frag}).exitCode, 0);
        QVERIFY(QFile::exists(png));
    }

    // A loop that never ends is named on its line before the driver drops it silently (a
    // warning), and a program that can never finish a frame is refused: exit 1, an error on
    // the loop's line.
    void checkNamesEndlessLoops()
    {
        const QString vert = m_dir.filePath("loop.vert"), frag = m_dir.filePath("loop.frag");
        QFile v(vert), f(frag);
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write("attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n");
        f.write("precision mediump float;\nvoid main() {\n  float x = 0.5;\n"
                "  for (;;) { x = x * 0.5; }\n  gl_FragColor = vec4(x);\n}\n");
        v.close();
        f.close();
        const Run r = run({"--check", "--vertex", vert, "--fragment", frag});
        QVERIFY2(r.out.contains((frag + ":4:3: warning: this loop never ends").toUtf8()),
                 r.out.constData());
        QVERIFY2(
            r.out.contains((frag + ":4:3: error: this program never finishes a frame").toUtf8()),
            r.out.constData());
        QCOMPARE(r.exitCode, 1);
    }

    // The class's other loops: a for (;;) with a side effect, a trivially endless one and one
    // of 10^9 steps (llvmpipe cuts it short and draws it fast, so only its text tells):
    // --check, --render and --probe exit 1 within 10 s with an error on the loop's line.
    void endlessLoopsExitWithOne_data()
    {
        QTest::addColumn<QString>("loop");
        QTest::addColumn<QString>("mode");
        const QStringList loops{"for (;;) { k += 0.5; }", "while (true) {}",
                                "for (int i = 0; i < 1000000000; i++) { k += 1e-6; }"};
        for (const QString &loop : loops)
            for (const QString mode : {"--check", "--render", "--probe"})
                QTest::newRow(qPrintable(mode + " " + loop)) << loop << mode;
    }

    void endlessLoopsExitWithOne()
    {
        QFETCH(QString, loop);
        QFETCH(QString, mode);
        const QString vert = m_dir.filePath("e.vert"), frag = m_dir.filePath("e.frag");
        QFile v(vert), f(frag);
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write("attribute vec4 vPosition;\nvoid main() { gl_Position = vPosition; }\n");
        f.write(("precision mediump float;\nvoid main() {\n  float k = 0.0;\n  " + loop +
                 "\n  gl_FragColor = vec4(k);\n}\n")
                    .toUtf8());
        v.close();
        f.close();
        QStringList args{mode};
        if (mode == "--render")
            args << m_dir.filePath("e.png");
        else if (mode == "--probe")
            args << "10,10";
        QElapsedTimer clock;
        clock.start();
        const Run r = run(args + QStringList{"--vertex", vert, "--fragment", frag});
        QVERIFY(clock.elapsed() < 10000);
        QCOMPARE(r.exitCode, 1);
        const QByteArray said = mode == "--check" ? r.out : r.err;
        QVERIFY2(
            said.contains((frag + ":4:3: error: this program never finishes a frame").toUtf8()),
            said.constData());
        QVERIFY(!QFile::exists(m_dir.filePath("e.png")));
    }

    // The issue's freezing loop (it ends, after ~65,000 steps a fragment on llvmpipe): tried
    // at a small size, its frame time at --size is over the budget; refused in bounded time
    // with the estimate on the loop's line, no image written.
    void slowProgramIsRefusedInBoundedTime()
    {
        const QString vert = m_dir.filePath("slow.vert"), frag = m_dir.filePath("slow.frag");
        QFile v(vert), f(frag);
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write("attribute vec4 vPosition;\nattribute vec4 vNormal;\nuniform mat4 mModelView;\n"
                "uniform mat4 mProjection;\nvarying vec3 fN;\nvoid main() {\n"
                "  fN = (mModelView * vec4(vNormal.xyz, 0.0)).xyz;\n"
                "  gl_Position = mProjection * mModelView * vPosition;\n}\n");
        f.write("precision mediump float;\nvarying vec3 fN;\nvoid main() {\n"
                "  vec3 N = normalize(fN);\n  float diffuse = max(N.z, 0.0);\n"
                "  float k = N.x + 2.0;\n  while (k > 0.0) { k = k * 1.0 + 0.0001; }\n"
                "  diffuse *= k;\n  gl_FragColor = vec4(vec3(diffuse), 1.0);\n}\n");
        v.close();
        f.close();
        const QString png = m_dir.filePath("slow.png");
        QElapsedTimer clock;
        clock.start();
        const Run r = run({"--render", png, "--vertex", vert, "--fragment", frag});
        QVERIFY(clock.elapsed() < 10000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains((frag + ":7:3: error: drawing one frame with this program at "
                                        "800x600 would take more than")
                                    .toUtf8()),
                 r.err.constData());
        QVERIFY(r.err.contains("an endless or very long loop?"));
        QVERIFY(!QFile::exists(png));
        // A bigger budget lets it draw.
        QCOMPARE(run({"--render", png, "--vertex", vert, "--fragment", frag, "--size", "64x48",
                      "--frame-budget", "60"})
                     .exitCode,
                 0);
    }

    // Values echoed in messages stay readable: a scene with 200,000 lights and a 2 MB mesh
    // path made megabyte lines on stderr; now the list is summarised and the path elided.
    void echoedValuesAreBounded()
    {
        QJsonObject scene;
        {
            const Run dump = run({"--save-scene", m_dir.filePath("plain.json"), "--render",
                                  m_dir.filePath("plain.png")});
            QCOMPARE(dump.exitCode, 0);
            QFile f(m_dir.filePath("plain.json"));
            QVERIFY(f.open(QIODevice::ReadOnly));
            scene = QJsonDocument::fromJson(f.readAll()).object();
        }
        QJsonArray lights;
        for (int i = 0; i < 200000; ++i)
            lights.append(QJsonObject{{"position", QJsonArray{0, 1, 2, 1}}});
        scene["lights"] = lights;
        QJsonArray objects = scene["objects"].toArray();
        QJsonObject object = objects[0].toObject();
        object["mesh"] = "/nowhere/" + QString(2'000'000, 'a') + ".obj";
        objects[0] = object;
        scene["objects"] = objects;
        const QString path = m_dir.filePath("echo.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(scene).toJson(QJsonDocument::Compact));
        f.close();
        const Run r = run({"--scene", path, "--render", m_dir.filePath("echo.png")});
        QCOMPARE(r.exitCode, 1); // the mesh cannot load
        QVERIFY2(r.err.size() < 8000, qPrintable(QString::number(r.err.size())));
        QVERIFY2(r.err.contains("lights[4] (at most 4 lights)"), r.err.left(500).constData());
        QVERIFY(r.err.contains(" more"));
        QVERIFY(r.err.contains("aaa...aaa"));
    }

    // Images are written through a temporary file and a rename: a kill at any moment of
    // --render leaves the old PNG whole (it turned into 8 KB nobody could decode), and a FIFO
    // or a device is never replaced by a file.
    void imageWritesAreAtomicAndSparePipes()
    {
        const QString png = m_dir.filePath("kept.png");
        QCOMPARE(run({"--render", png, "--size", "640x480"}).exitCode, 0);
        const QImage before(png);
        QVERIFY(!before.isNull());
        for (const int delay : {150, 300, 450, 600, 750, 900}) {
            QProcess p;
            p.start(LIGHTBENCH_EXE, {"--render", png, "--size", "3000x2000", "--kd", "0,1,0"});
            QVERIFY(p.waitForStarted());
            QTest::qWait(delay);
            p.kill();
            p.waitForFinished();
            const QImage now(png);
            QVERIFY2(!now.isNull(), qPrintable(QString("killed after %1 ms").arg(delay)));
            QVERIFY(now.size() == before.size() || now.size() == QSize(3000, 2000));
        }
        QCOMPARE(QDir(m_dir.path()).entryList({"kept.png*"}, QDir::Files),
                 QStringList{"kept.png"}); // no temporary file left behind

        const QString fifo = m_dir.filePath("pipe.png");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const Run r = run({"--render", fifo});
        QCOMPARE(r.exitCode, 2); // refused with the command line, before a frame is drawn
        QVERIFY2(r.err.contains("not a regular file"), r.err.constData());
        QVERIFY(!QFileInfo(fifo).isFile());
        const Run save = run({"--save-scene", fifo, "--render", m_dir.filePath("x.png")});
        QVERIFY(save.exitCode != 0);
        QVERIFY(!QFileInfo(fifo).isFile());
    }

    void shaderEditsSurviveAKill()
    {
        QTemporaryDir config;
        const QString vert = m_dir.filePath("kill.vert"), frag = m_dir.filePath("kill.frag");
        QFile v(vert), f(frag);
        QVERIFY(v.open(QIODevice::WriteOnly) && f.open(QIODevice::WriteOnly));
        v.write(
            "attribute vec4 vPosition; // marker-7f3a\nvoid main() { gl_Position = vPosition; }\n");
        f.write("precision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n");
        v.close();
        f.close();
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("XDG_CONFIG_HOME", config.path());
        QProcess window;
        window.setProcessEnvironment(env);
        window.start(LIGHTBENCH_EXE, {"--vertex", vert, "--fragment", frag});
        QVERIFY(window.waitForStarted());
        const QString conf = config.filePath("lightbench/lightbench.conf");
        auto saved = [&] {
            QFile c(conf);
            return c.open(QIODevice::ReadOnly) && c.readAll().contains("marker-7f3a");
        };
        QTRY_VERIFY_WITH_TIMEOUT(saved(), 20000);
        window.kill(); // SIGKILL: no close event, no last save
        QVERIFY(window.waitForFinished());
        QVERIFY(saved());
        // The next start comes up with them (and the window opens and draws).
        QProcess again;
        again.setProcessEnvironment(env);
        again.start(LIGHTBENCH_EXE, {"--screenshot", config.filePath("after.png")});
        QVERIFY(again.waitForFinished(60000));
        QCOMPARE(again.exitCode(), 0);
        QVERIFY(QFile::exists(config.filePath("after.png")));
        QVERIFY(saved());
    }

    void helpExitsWithZero()
    {
        const Run r = run({"--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--probe"));
    }
};

QTEST_GUILESS_MAIN(TestCliProcess)
#include "test_cli_process.moc"
