// Command line: every option reaches the scene; every bad value is refused with exit code 2
// and a message that names the option.
#include "command_line.h"
#include "lesson.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace lb;

namespace {
const QString kSlides = QStringLiteral(LB_TEST_DATA "/../../resources/lessons/slides.json");
const QString kExample = QStringLiteral(LB_TEST_DATA "/../../resources/examples/toon.json");
} // namespace

namespace {
CommandLineResult parse(const QString &args)
{
    return parseCommandLine(QStringList{"lightbench"} + args.split(' ', Qt::SkipEmptyParts));
}
Scene applied(const QString &args)
{
    const CommandLineResult r = parse(args);
    Scene s;
    if (r.commandLine)
        r.commandLine->applyTo(s);
    return s;
}
} // namespace

class TestCommandLine : public QObject
{
    Q_OBJECT
private slots:
    void optionsReachTheScene()
    {
        const Scene s =
            applied("--shape torus --tessellation 30 --shading gouraud --specular phong "
                    "--frame camera --light 1,-2,3,0 --ia 0.1,0.2,0.3 --id 0,0,1 "
                    "--is 0.5,0.5,0.5 --ka 0,1,0 --kd 1,1,0 --ks 0.2,0.2,0.2 "
                    "--shininess 250 --projection orthographic --camera-orbit 30,-10 "
                    "--model-rotate 10,20,30 --model-scale 2,1,0.5 --lighting off "
                    "--vertex-colors on --texture on --show-light off --cull-back-faces on "
                    "--terms diffuse,specular --attenuation 1,0.5,0.25 --spot 0,-1,0,30,4");
        QCOMPARE(s.objects[0].shape, Shape::Torus);
        QCOMPARE(s.objects[0].tessellation, 30);
        QCOMPARE(s.shading.shading, Shading::Gouraud);
        QCOMPARE(s.shading.specular, SpecularModel::Phong);
        QCOMPARE(s.lights[0].frame, LightFrame::Camera);
        QCOMPARE(s.lights[0].position, glm::vec4(1, -2, 3, 0));
        QCOMPARE(s.lights[0].colors.ia, glm::vec3(0.1f, 0.2f, 0.3f));
        QCOMPARE(s.lights[0].colors.id, glm::vec3(0, 0, 1));
        QCOMPARE(s.lights[0].colors.is, glm::vec3(0.5f));
        QCOMPARE(s.objects[0].material.ka, glm::vec3(0, 1, 0));
        QCOMPARE(s.objects[0].material.kd, glm::vec3(1, 1, 0));
        QCOMPARE(s.objects[0].material.ks, glm::vec3(0.2f));
        QCOMPARE(s.objects[0].material.shininess, 250.0f);
        QCOMPARE(s.shading.projection, Projection::Orthographic);
        QCOMPARE(s.camera.yawDegrees, 30.0f);
        QCOMPARE(s.camera.pitchDegrees, -10.0f);
        QCOMPARE(s.objects[0].rotationDegrees, glm::vec3(10, 20, 30));
        QCOMPARE(s.objects[0].scale, glm::vec3(2, 1, 0.5f));
        QVERIFY(!s.shading.lighting);
        QVERIFY(s.shading.vertexColors);
        QVERIFY(s.objects[0].texture);
        QVERIFY(!s.showLight);
        QVERIFY(s.objects[0].cullBackFaces);
        QVERIFY(!s.shading.terms.ambient);
        QVERIFY(s.shading.terms.diffuse && s.shading.terms.specular);
        QCOMPARE(s.lights[0].attenuation, glm::vec3(1, 0.5f, 0.25f));
        QCOMPARE(s.lights[0].spot.direction, glm::vec3(0, -1, 0));
        QCOMPARE(s.lights[0].spot.cutoffDegrees, 30.0f);
        QCOMPARE(s.lights[0].spot.exponent, 4.0f);
        QVERIFY(!applied("--terms none").shading.terms.specular);
        QVERIFY(applied("--terms specular").shading.terms.specular);
        QCOMPARE(applied("--show half").shading.show, ShowChoice::Half);
        QCOMPARE(applied("--show ndotl").shading.show, ShowChoice::NDotL);
    }

    void renderProbeAndSize()
    {
        const CommandLineResult r = parse("--render out.png --size 320x200 --probe 319,199");
        QVERIFY(r.commandLine);
        QCOMPARE(r.commandLine->renderPath, QString("out.png"));
        QCOMPARE(r.commandLine->size, QSize(320, 200));
        QCOMPARE(*r.commandLine->probe, QPoint(319, 199));
        QVERIFY(r.commandLine->headless());
        QVERIFY(!parse("--shape cube").commandLine->headless());
        QCOMPARE(parse("--render x.png").commandLine->size, QSize(800, 600));
    }

    void help()
    {
        const CommandLineResult r = parse("--help");
        QCOMPARE(r.exitCode, 0);
        QVERIFY(!r.commandLine);
        QVERIFY(r.message.contains("--probe"));
        QVERIFY(r.message.contains("--camera-orbit"));
    }

    // --version: the version of CMake's project() and nothing else, exit 0.
    void version()
    {
        for (const char *option : {"--version", "-v"}) {
            const CommandLineResult r = parse(option);
            QCOMPARE(r.exitCode, 0);
            QVERIFY(!r.commandLine);
            QCOMPARE(r.message, QString("lightbench " LB_PROJECT_VERSION "\n"));
        }
        QVERIFY(parse("--help").message.startsWith("Usage: lightbench [options] [FILE...]\n"));
    }

    // FILE... (the desktop's `lightbench %F`) is for the window to open, made absolute and
    // read there (nothing is read here: a missing file or a FIFO is the window's to say);
    // with --grade, the submissions as before.
    void fileArgumentsOpenInTheWindow()
    {
        const CommandLineResult r = parse("a.lbscene /nowhere/b.json --shading flat c.lblesson");
        QVERIFY2(r.commandLine, qPrintable(r.message));
        QVERIFY(!r.commandLine->headless());
        QCOMPARE(r.commandLine->filePaths,
                 QStringList({QDir::current().absoluteFilePath("a.lbscene"), "/nowhere/b.json",
                              QDir::current().absoluteFilePath("c.lblesson")}));
        QVERIFY(r.commandLine->scenePath.isEmpty() && r.commandLine->lessonPath.isEmpty());
        QVERIFY(parse("--screenshot s.png a.lbscene").commandLine); // the window, then a grab
        QVERIFY(parse("--shading flat").commandLine->filePaths.isEmpty());
        const CommandLineResult grade = parse("--grade x.vert y --exercise e.json");
        QVERIFY2(grade.commandLine, qPrintable(grade.message));
        QCOMPARE(grade.commandLine->submissions, QStringList({"x.vert", "y"}));
        QVERIFY(grade.commandLine->filePaths.isEmpty());
    }

    // --object lists the objects; the object options apply to the last one named.
    void objectsAndTheirOptions()
    {
        const Scene s = applied("--object cube --object torus --object /tmp/teapot.obj "
                                "--model-translate 1,2,-3 --kd 0,0,1 --texture on "
                                "--frame object --light-object 1");
        QCOMPARE(int(s.objects.size()), 3);
        QCOMPARE(s.objects[0].shape, Shape::Cube);
        QCOMPARE(s.objects[1].shape, Shape::Torus);
        QCOMPARE(s.objects[2].meshPath, QString("/tmp/teapot.obj"));
        QCOMPARE(s.selected, 2);
        QCOMPARE(s.objects[2].translation, glm::vec3(1, 2, -3));
        QCOMPARE(s.objects[0].translation, glm::vec3(-2.5f, 0, 0)); // placed in a row
        QCOMPARE(s.objects[2].material.kd, glm::vec3(0, 0, 1));
        QCOMPARE(s.objects[0].material.kd, Material{}.kd);
        QVERIFY(s.objects[2].texture && !s.objects[0].texture);
        QCOMPARE(s.lights[0].frame, LightFrame::Object);
        QCOMPARE(s.lights[0].object, 1);
        QVERIFY(s.camera.distance > OrbitCamera{}.distance); // framed
        // An image for the last object: its path made absolute, the texture switched on; an
        // explicit --texture off still wins.
        const Scene image = applied("--object cube --object sphere --texture-file bricks.png "
                                    "--texture-wrap clamp --texture-filter nearest "
                                    "--texture-mipmaps on");
        QCOMPARE(image.objects[1].textureFile, QDir::current().absoluteFilePath("bricks.png"));
        QVERIFY(image.objects[1].texture);
        QVERIFY(image.objects[1].sampling ==
                (TextureSampling{TextureWrap::Clamp, TextureFilter::Nearest, true}));
        QVERIFY(image.objects[0].textureFile.isEmpty());
        QVERIFY(!applied("--texture-file a.png --texture off").objects[0].texture);
        // Without --object, the one object as before.
        const Scene one = applied("--model-translate 0,1,0 --shape cube");
        QCOMPARE(int(one.objects.size()), 1);
        QCOMPARE(one.objects[0].translation, glm::vec3(0, 1, 0));
        QCOMPARE(one.objects[0].shape, Shape::Cube);
    }

    void badValues_data()
    {
        QTest::addColumn<QString>("args");
        QTest::addColumn<QString>("named"); // what the message must name
        QTest::newRow("translate, two numbers") << "--model-translate 1,2"
                                                << "--model-translate";
        QTest::newRow("translate, too far") << "--model-translate 0,5000,0"
                                            << "--model-translate";
        QTest::newRow("light object, negative") << "--light-object -1"
                                                << "--light-object";
        QTest::newRow("light object, none such") << "--object cube --light-object 1"
                                                 << "--light-object";
        QTest::newRow("texture wrap") << "--texture-wrap mirror"
                                      << "--texture-wrap";
        QTest::newRow("texture filter") << "--texture-filter cubic"
                                        << "--texture-filter";
        QTest::newRow("texture mipmaps") << "--texture-mipmaps maybe"
                                         << "--texture-mipmaps";
        QTest::newRow("texture file, empty") << "--texture-file="
                                             << "--texture-file";
        QTest::newRow("exercise without grade") << "--exercise e.json"
                                                << "--exercise";
        QTest::newRow("grade without exercise") << "--grade a.vert"
                                                << "--grade";
        QTest::newRow("grade without submissions") << "--grade --exercise e.json"
                                                   << "--grade";
        QTest::newRow("negative seed") << "--grade a --exercise e.json --seed -3"
                                       << "--seed";
        QTest::newRow("scene beside grade") << "--grade a --exercise e.json --scene s.json"
                                            << "--scene";
        QTest::newRow("size beside grade") << "--grade a --exercise e.json --size 64x64"
                                           << "--size";
        QTest::newRow("missing number") << "--light 1,2,3"
                                        << "--light";
        QTest::newRow("empty number") << "--ka 1,,0"
                                      << "--ka";
        QTest::newRow("nan") << "--shininess nan"
                             << "--shininess";
        QTest::newRow("inf") << "--light inf,0,0,1"
                             << "--light";
        QTest::newRow("w = 0.5") << "--light 1,2,3,0.5"
                                 << "--light";
        QTest::newRow("zero direction") << "--light 0,0,0,0"
                                        << "--light";
        QTest::newRow("unknown shape") << "--shape teapot"
                                       << "--shape";
        QTest::newRow("unknown shading") << "--shading toon"
                                         << "--shading";
        QTest::newRow("unknown frame") << "--frame screen"
                                       << "--frame";
        QTest::newRow("unknown specular") << "--specular cook"
                                          << "--specular";
        QTest::newRow("unknown projection") << "--projection fisheye"
                                            << "--projection";
        QTest::newRow("size 0") << "--render a.png --size 0x600"
                                << "--size";
        QTest::newRow("size 100000") << "--render a.png --size 100000x100000"
                                     << "--size";
        QTest::newRow("size words") << "--size big"
                                    << "--size";
        QTest::newRow("step without lesson") << "--step 2"
                                             << "--step";
        QTest::newRow("lesson beside scene") << "--lesson l.json --scene s.json"
                                             << "--lesson";
        QTest::newRow("lesson missing") << "--lesson /nonexistent/lesson.json"
                                        << "--lesson";
        QTest::newRow("lesson step past the end") << "--lesson " + kSlides + " --step 99"
                                                  << "--step";
        QTest::newRow("lesson step 0") << "--lesson " + kSlides + " --step 0"
                                       << "--step";
        QTest::newRow("colour above 1") << "--id 2,0,0"
                                        << "--id";
        QTest::newRow("negative colour") << "--is -1,0,0"
                                         << "--is";
        QTest::newRow("shininess 0") << "--shininess 0"
                                     << "--shininess";
        QTest::newRow("shininess 5000") << "--shininess 5000"
                                        << "--shininess";
        QTest::newRow("scale 0") << "--model-scale 0,1,1"
                                 << "--model-scale";
        QTest::newRow("pitch 120") << "--camera-orbit 0,120"
                                   << "--camera-orbit";
        QTest::newRow("probe outside") << "--probe 800,10"
                                       << "--probe";
        QTest::newRow("probe words") << "--probe a,b"
                                     << "--probe";
        QTest::newRow("lighting maybe") << "--lighting maybe"
                                        << "--lighting";
        QTest::newRow("tessellation 1") << "--tessellation 1"
                                        << "--tessellation";
        QTest::newRow("unknown show") << "--show tangent"
                                      << "--show";
        QTest::newRow("unknown term") << "--terms ambient,emissive"
                                      << "--terms";
        QTest::newRow("empty terms") << "--terms ,"
                                     << "--terms";
        QTest::newRow("negative attenuation") << "--attenuation 1,-0.5,0"
                                              << "--attenuation";
        QTest::newRow("zero attenuation") << "--attenuation 0,0,0"
                                          << "--attenuation";
        QTest::newRow("attenuation of two") << "--attenuation 1,2"
                                            << "--attenuation";
        QTest::newRow("cutoff over 180") << "--spot 0,0,-1,200,1"
                                         << "--spot";
        QTest::newRow("negative cutoff") << "--spot 0,0,-1,-5,1"
                                         << "--spot";
        QTest::newRow("zero spot direction") << "--spot 0,0,0,30,1"
                                             << "--spot";
        QTest::newRow("tiny spot direction") << "--spot 1e-30,0,0,30,1"
                                             << "--spot";
        QTest::newRow("spot exponent 500") << "--spot 0,0,-1,30,500"
                                           << "--spot";
        QTest::newRow("spot of four") << "--spot 0,0,-1,30"
                                      << "--spot";
        QTest::newRow("unknown option") << "--teapot"
                                        << "teapot";
        QTest::newRow("missing value") << "--shape"
                                       << "shape";
        // FILE... opens in the window: beside a headless mode, --scene or --lesson, refused.
        QTest::newRow("stray argument, render") << "--render a.png sphere"
                                                << "unexpected argument 'sphere'";
        QTest::newRow("stray argument, probe") << "--probe 1,1 a.lbscene"
                                               << "unexpected argument 'a.lbscene'";
        QTest::newRow("stray argument, save-scene") << "--save-scene s.json a.lblesson"
                                                    << "unexpected argument 'a.lblesson'";
        QTest::newRow("file beside lesson") << "--lesson " + kSlides + " b.lbscene"
                                            << "--lesson: opens one file in the window; "
                                               "'b.lbscene' is another";
        QTest::newRow("file beside scene") << "--scene " + kExample + " b.lbscene"
                                           << "--scene: opens one file";
    }

    // A lesson's step is the scene, as --scene's file would be; its program comes along.
    void aLessonStepIsTheScene()
    {
        const LessonRead lesson = readLessonFile(kSlides);
        QVERIFY2(lesson.lesson, qPrintable(lesson.error));
        for (int step : {1, 8, 14}) {
            const CommandLineResult r =
                parse(QString("--lesson %1 --step %2 --render x.png").arg(kSlides).arg(step));
            QVERIFY2(r.commandLine, qPrintable(r.message));
            const LessonStep &expected = lesson.lesson->steps[std::size_t(step - 1)];
            QVERIFY(r.commandLine->sceneFile);
            QVERIFY(r.commandLine->sceneFile->scene == expected.scene.scene);
            QCOMPARE(r.commandLine->programFromScene, expected.scene.program.has_value());
            QCOMPARE(r.commandLine->lessonStep, step);
        }
        const CommandLineResult first = parse("--lesson " + kSlides + " --render x.png");
        QVERIFY(first.commandLine && first.commandLine->lessonStep == 1);
    }

    void badValues()
    {
        QFETCH(QString, args);
        QFETCH(QString, named);
        const CommandLineResult r = parse(args);
        QVERIFY(!r.commandLine);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.message.contains(named), qPrintable(r.message));
        QVERIFY2(!r.message.contains('\n'), qPrintable(r.message));
    }

    // Shader files are refused before a byte is read when they are no regular file or too
    // big: /dev/zero grew without end (and died of bad_alloc under a memory limit), a FIFO
    // would wait for a writer forever.
    void shaderFilesAreBoundedBeforeReading_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("named");
        QTest::newRow("/dev/zero") << "device"
                                   << "/dev/zero: not a regular file";
        QTest::newRow("a FIFO") << "fifo"
                                << "not a regular file";
        QTest::newRow("a folder") << "folder"
                                  << "not a regular file";
        QTest::newRow("2 MiB") << "big"
                               << "2048 KiB is more than a shader may be (1024 KiB)";
        QTest::newRow("missing") << "missing"
                                 << "no such file";
    }

    // What the command line writes is checked with it, before any frame is drawn: a device,
    // a FIFO, a folder, a loop of links or a missing folder at the path is refused, exit 2,
    // and nothing there is replaced.
    void outputsThatCannotBeFilesAreRefusedFirst_data()
    {
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("named");
        for (const char *option : {"render", "save-scene", "screenshot"}) {
            QTest::addRow("--%s /dev/null", option) << option << "device"
                                                    << "/dev/null: not a regular file";
            QTest::addRow("--%s FIFO", option) << option << "fifo"
                                               << "out: not a regular file";
            QTest::addRow("--%s folder", option) << option << "folder"
                                                 << "out: not a regular file";
            QTest::addRow("--%s link loop", option) << option << "loop"
                                                    << "out: a loop of symbolic links";
            QTest::addRow("--%s missing folder", option) << option << "missing"
                                                         << "does not exist";
        }
    }

    void outputsThatCannotBeFilesAreRefusedFirst()
    {
        QFETCH(QString, option);
        QFETCH(QString, kind);
        QFETCH(QString, named);
        QTemporaryDir dir;
        QString path = dir.filePath("out");
        if (kind == "device")
            path = "/dev/null";
        else if (kind == "fifo")
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        else if (kind == "folder")
            QVERIFY(QDir(dir.path()).mkdir("out"));
        else if (kind == "loop")
            QVERIFY(QFile::link(path, path));
        else
            path = dir.filePath("nowhere/out.png");
        const CommandLineResult r = parse("--" + option + " " + path);
        QVERIFY(!r.commandLine);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.message.contains("--" + option) && r.message.contains(named),
                 qPrintable(r.message));
        if (kind == "fifo")
            QVERIFY(QFileInfo(path).exists() && !QFileInfo(path).isFile());
    }

    void shaderFilesAreBoundedBeforeReading()
    {
        QFETCH(QString, kind);
        QFETCH(QString, named);
        QTemporaryDir dir;
        QString path = dir.filePath("shader.frag");
        if (kind == "device")
            path = "/dev/zero";
        else if (kind == "fifo")
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        else if (kind == "folder")
            QVERIFY(QDir(dir.path()).mkdir("shader.frag"));
        else if (kind == "big") {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(2 * 1024 * 1024, ' '));
        }
        const CommandLineResult r = parse("--vertex " + path + " --fragment " + path);
        QVERIFY(!r.commandLine);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.message.contains(named), qPrintable(r.message));
        QVERIFY2(r.message.contains("--vertex"), qPrintable(r.message));
    }
};

QTEST_APPLESS_MAIN(TestCommandLine)
#include "test_command_line.moc"
