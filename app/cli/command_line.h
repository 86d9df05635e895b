#pragma once
// The command line: scene options shared by the window and the headless modes, plus
// --render, --probe, --size, --screenshot and --bench-frames. Bad values end the program with
// exit code 2 and one line naming the option; nothing here touches OpenGL.

#include "import_process.h"
#include "plots.h"
#include "scene.h"
#include "scene_file.h"

#include <QPoint>
#include <QSize>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace lb {

struct CommandLine
{
    // --scene FILE: the scene to start from (every other scene option overrides it), read
    // while parsing; what it ignored is listed once on stderr. Its program is the user
    // program unless --vertex/--fragment are given.
    QString scenePath;
    std::optional<SceneFile> sceneFile;
    QStringList sceneIgnored;
    // --lesson FILE --step N: the step's scene is the scene file's above (scenePath names the
    // lesson and the step); the window opens the lesson there.
    QString lessonPath;
    int lessonStep = 1;
    // FILE...: scene or lesson files for the window to open (absolute), as the desktop's
    // `lightbench %F` gives them; never with --scene, --lesson or a headless mode. Read by
    // the window, which says what is wrong with one (file_arguments.h).
    QStringList filePaths;
    QString saveScenePath; // --save-scene FILE: write the resulting scene, then go on or exit
    bool programFromScene = false;
    // Each scene option given, in order; applied on top of the default or the saved scene.
    std::vector<std::function<void(Scene &)>> sceneOverrides;
    QString renderPath;          // --render FILE.png (with --plot, .png or .svg)
    std::optional<QPoint> probe; // --probe X,Y
    // --plot KIND [--plot-data FILE.csv]: the model's curve into --render instead of a
    // frame, its samples into the CSV; --probe marks that pixel's point (plot_output.h).
    std::optional<PlotKind> plot;
    QString plotDataPath;
    QSize size{800, 600};   // --size WxH
    QString screenshotPath; // --screenshot FILE.png (window mode: grab and quit)
    int benchFrames = 0;    // --bench-frames N (headless timing)
    // --vertex FILE --fragment FILE: the user's program instead of the built-in pair.
    QString vertexPath, fragmentPath;
    QString vertexSource, fragmentSource;
    double frameBudgetSeconds = 1.0;   // --frame-budget: a user program slower is refused
    bool presentation = false;         // --presentation: the window full screen, presentation scale
    bool translateWebGl1 = false;      // --translate-webgl1: WebGL 1 shaders as GLSL 3.30
    std::optional<int> uiScalePercent; // --ui-scale PERCENT
    std::optional<QString> language;   // --language: "" (the system's), "en", "pt", "de"
    bool check = false; // --check: compile and link them, print diagnostics, exit 0 or 1
    int benchEdits = 0; // --bench-edits N (window: edit-to-pixels timing; --vertex/--fragment
                        // add a second pair to time)
    // --import-memory-limit MB, --import-time-limit S; unset: the preferences' (window) or
    // the defaults (headless).
    // --grade SUBMISSION... --exercise FILE [--report FILE|- [--report-format WORD]]
    // [--sheets DIR] [--seed N] (grade.h); --grade-one SUBMISSION is one submission, in the
    // batch's child process; --grade-prepare DIR draws the frames the batch hands its
    // children in DIR (--grade-frames DIR), in a child of its own (grade_frames.h).
    bool grade = false;
    QStringList submissions;
    QString gradeOne, gradeName; // --grade-name: the name the batch gives it (unique)
    QString gradePrepare, gradeFrames;
    QString exercisePath, reportPath, sheetsDir; // reportPath "-": standard output
    int reportFormat = 0; // a ReportFormat (grading_formats.h): csv unless --report-format
    std::uint32_t seed = 1;
    std::optional<qint64> importMemoryMB;
    std::optional<int> importSeconds;
    ImportLimits importLimits() const;

    bool hasUserProgram() const { return !vertexPath.isEmpty(); }
    bool headless() const
    {
        return !renderPath.isEmpty() || probe || plot || benchFrames > 0 || check ||
               !saveScenePath.isEmpty() || grade || !gradeOne.isEmpty() || !gradePrepare.isEmpty();
    }
    // The scene options given, on top of `scene`.
    void applyTo(Scene &scene) const;
    // Headless: the scene file's scene (or the defaults) with the options applied.
    Scene headlessScene() const;
    // The program for --save-scene: --vertex/--fragment, the scene file's, or none.
    std::optional<ProgramText> program() const;
};

struct CommandLineResult
{
    std::optional<CommandLine> commandLine; // empty when the program should exit at once
    int exitCode = 0;                       // 0 for --help, 2 for a bad command line
    QString message;                        // help text, or the one-line error
};

// `arguments` starts with the program name, as QCoreApplication::arguments() does.
// --version's message is "lightbench VERSION\n", the version of CMake's project().
CommandLineResult parseCommandLine(const QStringList &arguments);

// An option as --help, the man page and the shell's completion show it.
struct OptionInfo
{
    QStringList names;   // "h", "help": the one-letter name first, the long one last
    QString valueName;   // "FILE.png", "gouraud|phong|flat"; empty: the option takes none
    QString description; // one paragraph, English
    // What its value can be, for the completion: fixed words (the list the parser checks
    // against), files (ending in one of `suffixes`; any file when there are none), a folder.
    // None of them: a number or a list, with nothing to offer.
    QStringList words;
    bool files = false;
    QStringList suffixes; // "png", "json": without the dot, in lower case
    bool directory = false;

    QString longName() const { return names.last(); }
};

// Every option --help lists, in its order (the grading child's hidden ones left out).
std::vector<OptionInfo> visibleOptions();
// What FILE... arguments are, as --help says it.
QString fileArgumentsHelp();
// The endings of scene and lesson files: lightbench's own first (.lbscene, .lblesson: the
// desktop's MIME types), then .json (which holds either: its content decides).
QStringList sceneFileSuffixes();
QStringList lessonFileSuffixes();
// --language's values ("system" first: the system's language) and the switches' on|off.
QStringList commandLineLanguages();
QStringList onOffNames();

} // namespace lb
