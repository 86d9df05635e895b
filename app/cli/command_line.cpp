#include "command_line.h"

#include "lightbench_version.h"

#include "command_line_grade.h"
#include "command_line_plot.h"
#include "command_line_scene.h"
#include "exercise.h"
#include "lesson.h"
#include "option_values.h"

#include "message_text.h"
#include "safe_write.h"
#include "shader_document.h"

#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>

namespace lb {

namespace {

using namespace options;

void parseInto(const QCommandLineParser &parser, CommandLine &cl)
{
    auto given = [&](const char *name) { return parser.isSet(QString::fromLatin1(name)); };
    auto value = [&](const char *name) { return parser.value(QString::fromLatin1(name)); };

    if (given("size")) {
        const QStringList wh = value("size").split('x');
        if (wh.size() != 2)
            fail("size", QString("expected WxH, got '%1'").arg(echoed(value("size"))));
        cl.size = QSize(integer("size", wh[0], 1, 8192), integer("size", wh[1], 1, 8192));
    }
    // Output files are checked before any work: a device, a FIFO or a folder in their place, a
    // folder that is not there or cannot be written is said now, not after the frame is drawn.
    const auto output = [&](const char *option) {
        const QString path = value(option);
        if (path.isEmpty())
            fail(option, "needs a file name");
        if (const QString why = unwritableTarget(path); !why.isEmpty())
            fail(option, why);
        return path;
    };
    if (given("render"))
        cl.renderPath = output("render");
    if (given("probe")) {
        const QStringList xy = value("probe").split(',');
        if (xy.size() != 2)
            fail("probe", QString("expected X,Y, got '%1'").arg(echoed(value("probe"))));
        cl.probe = QPoint(integer("probe", xy[0], 0, cl.size.width() - 1),
                          integer("probe", xy[1], 0, cl.size.height() - 1));
    }
    if (given("screenshot"))
        cl.screenshotPath = output("screenshot");
    if (given("bench-frames"))
        cl.benchFrames = integer("bench-frames", value("bench-frames"), 1, 100000);
    if (given("bench-edits"))
        cl.benchEdits = integer("bench-edits", value("bench-edits"), 1, 10000);
    if (given("vertex") != given("fragment"))
        fail(given("vertex") ? "vertex" : "fragment", "--vertex and --fragment go together");
    if (given("vertex")) {
        cl.vertexPath = value("vertex");
        cl.fragmentPath = value("fragment");
        cl.vertexSource = readShader("vertex", cl.vertexPath);
        cl.fragmentSource = readShader("fragment", cl.fragmentPath);
    }
    if (given("scene") && given("lesson"))
        fail("lesson", "--lesson and --scene do not go together: the lesson's step is the scene");
    if (given("step") && !given("lesson"))
        fail("step", "--step goes with --lesson");
    if (given("scene")) {
        cl.scenePath = value("scene");
        SceneFileRead read = readSceneFile(cl.scenePath);
        if (!read.file)
            fail("scene", read.error);
        cl.sceneFile = std::move(read.file);
        cl.sceneIgnored = read.ignored;
    } else if (given("lesson")) {
        cl.lessonPath = value("lesson");
        const LessonRead read = readLessonFile(cl.lessonPath);
        if (!read.lesson)
            fail("lesson", read.error);
        const int steps = int(read.lesson->steps.size());
        cl.lessonStep = given("step") ? integer("step", value("step"), 1, steps) : 1;
        const LessonStep &step = read.lesson->steps[std::size_t(cl.lessonStep - 1)];
        if (!step.error.isEmpty())
            fail("step", QString("%1: %2").arg(echoed(cl.lessonPath), step.error));
        cl.scenePath = cl.lessonPath + QString(" (step %1)").arg(cl.lessonStep);
        cl.sceneFile = step.scene;
        // What the lesson and this step ignored; the other steps' notes are theirs.
        const QString here = QString("step %1: ").arg(cl.lessonStep);
        for (const QString &note : read.ignored)
            if (note.startsWith(here) || !note.startsWith("step "))
                cl.sceneIgnored << note;
    }
    if (cl.sceneFile) {
        if (!given("vertex") && cl.sceneFile->program) {
            cl.programFromScene = true;
            cl.vertexPath = cl.scenePath + " (vertex)";
            cl.fragmentPath = cl.scenePath + " (fragment)";
            cl.vertexSource = cl.sceneFile->program->vertex;
            cl.fragmentSource = cl.sceneFile->program->fragment;
        }
    }
    if (given("save-scene"))
        cl.saveScenePath = output("save-scene");
    if (given("frame-budget")) {
        const float v = numbers("frame-budget", value("frame-budget"), 1, "seconds")[0];
        checkRange("frame-budget", v, float(kMinFrameBudget), float(kMaxFrameBudget));
        cl.frameBudgetSeconds = double(v);
    }
    cl.presentation = given("presentation");
    cl.translateWebGl1 = given("translate-webgl1");
    if (given("ui-scale"))
        cl.uiScalePercent = integer("ui-scale", value("ui-scale"), 100, 250);
    if (given("language")) {
        const QString language = value("language");
        const QStringList languages = commandLineLanguages(); // "system" first
        if (!languages.contains(language))
            fail("language",
                 QString("expected %1, got '%2'").arg(languages.join('|'), echoed(language)));
        cl.language = language == languages[0] ? QString() : language;
    }
    cl.check = given("check");
    if (const QString error = parseGradeOptions(parser, cl); !error.isEmpty())
        throw BadOption{error};
    if (const QString error = parsePlotOptions(parser, cl); !error.isEmpty())
        throw BadOption{error};
    if (cl.check && !cl.hasUserProgram())
        fail("check", "needs --vertex FILE and --fragment FILE");
    parseSceneOptions(parser, cl);
}

} // namespace

ImportLimits CommandLine::importLimits() const
{
    ImportLimits limits;
    if (importMemoryMB)
        limits.memoryMB = *importMemoryMB;
    if (importSeconds)
        limits.seconds = *importSeconds;
    return limits;
}

void CommandLine::applyTo(Scene &scene) const
{
    for (const auto &f : sceneOverrides)
        f(scene);
}

Scene CommandLine::headlessScene() const
{
    Scene scene = sceneFile ? sceneFile->scene : Scene{};
    applyTo(scene);
    return scene;
}

std::optional<ProgramText> CommandLine::program() const
{
    if (programFromScene)
        return sceneFile->program;
    if (hasUserProgram())
        return ProgramText{plainText(QFileInfo(vertexPath).completeBaseName()), vertexSource,
                           fragmentSource};
    return std::nullopt;
}

CommandLineResult parseCommandLine(const QStringList &arguments)
{
    QCommandLineParser parser;
    // The batch's child processes (grade.h), not for people: one submission, its name in the
    // report; the batch's frames, drawn once by a child of their own and read by the others.
    const QList<QCommandLineOption> children{
        {"grade-one", "One submission of --grade.", "SUBMISSION"},
        {"grade-name", "Its name in the report.", "NAME"},
        {"grade-prepare", "Draws the batch's frames into DIR.", "DIR"},
        {"grade-frames", "The batch's frames, from DIR.", "DIR"}};
    for (QCommandLineOption child : children) {
        child.setFlags(QCommandLineOption::HiddenFromHelp);
        parser.addOption(child);
    }
    parser.setApplicationDescription(
        "lightbench: a lighting workbench for the Phong and Blinn-Phong models.\n"
        "Without --render, --probe or --bench-frames it opens the window.");
    for (const OptionInfo &o : visibleOptions())
        parser.addOption(QCommandLineOption(o.names, o.description, o.valueName));
    parser.addPositionalArgument("FILE", fileArgumentsHelp(), "[FILE...]");

    CommandLineResult result;
    if (!parser.parse(arguments)) {
        result.exitCode = 2;
        result.message = echoed(parser.errorText(), 200) + " (see --help)";
        return result;
    }
    if (parser.isSet("help")) {
        // Parsed before QCoreApplication exists, which is where Qt would take the name from.
        result.message = parser.helpText().replace("<executable_name>", "lightbench");
        return result;
    }
    if (parser.isSet("version")) {
        result.message = QStringLiteral("lightbench " LIGHTBENCH_VERSION "\n");
        return result;
    }
    try {
        CommandLine cl;
        parseInto(parser, cl);
        const QStringList files = parser.positionalArguments();
        if (!files.isEmpty() && !cl.grade) {
            // Files open in the window (the desktop's `lightbench %F`); a headless run draws
            // --scene's or --lesson's scene, and one file opens there, not two.
            if (cl.headless())
                throw BadOption{
                    QString("unexpected argument '%1' (see --help)").arg(echoed(files.first()))};
            if (!cl.scenePath.isEmpty())
                fail(cl.lessonPath.isEmpty() ? "scene" : "lesson",
                     QString("opens one file in the window; '%1' is another (give one of them)")
                         .arg(echoed(files.first())));
            for (const QString &file : files)
                cl.filePaths << (file.isEmpty() ? file : QFileInfo(file).absoluteFilePath());
        }
        result.commandLine = std::move(cl);
    } catch (const BadOption &bad) {
        result.exitCode = 2;
        result.message = bad.message;
    }
    return result;
}

} // namespace lb
