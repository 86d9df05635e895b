// lightbench.1, written from the options the parser knows (cli_docs.h). The prose around
// them says what the code does: the exit codes of main.cpp, run_command_line.cpp, headless.cpp and
// grade.cpp, the settings of run_window.cpp, the variables the code reads that a user would set.
#include "cli_docs.h"

#include "command_line.h"
#include "lightbench_version.h"

#include <QStringList>

#include <utility>

namespace lb {

namespace {

QString bold(const QString &text)
{
    return "\\fB" + roffEscaped(text) + "\\fR";
}

QString italic(const QString &text)
{
    return "\\fI" + roffEscaped(text) + "\\fR";
}

// A paragraph of plain text (escaped), then a line break in the source.
QString text(const QString &line)
{
    return roffEscaped(line) + "\n";
}

// An indented paragraph under a tag already in roff: .TP's form.
QString tagged(const QString &tag, const QString &body)
{
    return ".TP\n" + tag + "\n" + text(body);
}

// "--shading gouraud|phong|flat" with the fixed words in bold and placeholders in italic.
QString optionTag(const OptionInfo &o)
{
    QStringList names;
    for (const QString &name : o.names)
        names << bold((name.size() == 1 ? "-" : "--") + name);
    QString tag = names.join(", ");
    if (o.valueName.isEmpty())
        return tag;
    if (!o.words.isEmpty() && !o.files) {
        QStringList words;
        for (const QString &word : o.words)
            words << bold(word);
        return tag + " " + words.join("|");
    }
    return tag + " " + italic(o.valueName);
}

QString suffixList(const QStringList &suffixes)
{
    QStringList patterns;
    for (const QString &suffix : suffixes)
        patterns << italic("*." + suffix);
    return patterns.join(", ");
}

} // namespace

QString roffEscaped(const QString &text)
{
    QString out;
    bool lineStart = true;
    for (const uint c : text.toUcs4()) {
        // A control character at a line's start would make the line a request.
        if (lineStart && (c == '.' || c == '\''))
            out += "\\&";
        lineStart = c == '\n';
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else if (c > 126) // groff's Unicode escape: upper-case hex, at least 4 digits
            out += "\\[u" + QString::number(c, 16).toUpper().rightJustified(4, '0') + "]";
        else
            out += QChar(c);
    }
    return out;
}

QString manPage()
{
    QString page;
    page += ".\\\" Written by lightbench-docs from the options lightbench knows; do not edit.\n";
    page += QString(".TH LIGHTBENCH 1 \"\" \"lightbench %1\" \"User Commands\"\n")
                .arg(QStringLiteral(LIGHTBENCH_VERSION));
    page += ".SH NAME\n" +
            text("lightbench - a workbench for the lighting model of computer graphics courses");

    page += ".SH SYNOPSIS\n";
    page += bold("lightbench") + " [" + italic("OPTION") + "]... [" + italic("FILE") + "]...\n";
    page += ".br\n" + bold("lightbench") + " " + bold("--render") + " " + italic("FILE.png") +
            " [" + italic("OPTION") + "]...\n";
    page += ".br\n" + bold("lightbench") + " " + bold("--grade") + " " + italic("SUBMISSION") +
            "... " + bold("--exercise") + " " + italic("FILE.json") + " [" + bold("--report") +
            " " + italic("FILE.csv") + "] [" + bold("--sheets") + " " + italic("DIR") + "] [" +
            bold("--seed") + " " + italic("N") + "]\n";

    page += ".SH DESCRIPTION\n";
    page += text("lightbench shows the lighting model taught in computer graphics courses: "
                 "ambient, diffuse and specular terms, Phong and Blinn-Phong, Gouraud, Phong and "
                 "flat shading, the light in camera, world or object coordinates, every pixel "
                 "checked against a CPU reference of the same model. Its window has panels for "
                 "the lights, the material and the objects, a shader editor, a probe, compare "
                 "views, lessons and exercises (Check My Work).");
    page += ".PP\n" +
            text("Without --render, --probe, --check, --save-scene, --bench-frames or --grade it "
                 "opens the window: the options then change the scene the last session left. "
                 "The headless modes start from --scene's file or the default scene, never "
                 "from the session, and need an X server for OpenGL (xvfb-run(1) gives one).");
    page += ".PP\n" + italic("FILE") + "...: " +
            text(fileArgumentsHelp() + " A file that cannot be opened is named in the window "
                                       "with the reason, and the window opens as it would "
                                       "without it.");

    page += ".SH OPTIONS\n";
    for (const OptionInfo &o : visibleOptions())
        page += tagged(optionTag(o), o.description);

    page += ".SH FILES\n";
    page += tagged(suffixList(sceneFileSuffixes()),
                   "A scene: lights, material, objects, camera, the shaders inline and an "
                   "exercise's section (--scene, File > Open Scene). Saved without an ending, a "
                   "scene gets .json, or .lbscene where that filter was chosen.");
    page += tagged(suffixList(lessonFileSuffixes()),
                   "A lesson: steps of scenes with captions (--lesson, File > Open Lesson). A "
                   ".json file is a lesson when it says so (\"format\": \"lightbench-lesson\").");
    page += tagged(italic("$XDG_CONFIG_HOME/lightbench/lightbench.conf"),
                   "The window's session and preferences (~/.config when XDG_CONFIG_HOME is "
                   "unset): the scene, the editor's text, the layout, the language. The "
                   "headless modes do not read it.");
    page += tagged(italic("$TMPDIR/lightbench-unsaved-DATE.json"),
                   "The scene and program of a window closed while the session could not be "
                   "saved (a full disk), named on standard error.");

    page += ".SH ENVIRONMENT\n";
    page += tagged(bold("LANG") + ", " + bold("LC_ALL") + ", " + bold("LC_MESSAGES"),
                   "The window's language when View > Language is System (English, Portuguese "
                   "or German; any other gives English). The command line's output is English "
                   "whatever they say.");
    page += tagged(bold("DISPLAY") + ", " + bold("WAYLAND_DISPLAY"),
                   "The display the window, and the headless modes' OpenGL, need.");
    page += tagged(bold("LIGHTBENCH_PROGRAM_MEMORY_MB"),
                   "How much memory the driver may take compiling and trying one of your "
                   "programs (default 2048).");
    page += tagged(bold("LIGHTBENCH_GRADE_PROCESSES"),
                   "How many submissions --grade grades at once (default one per core, at most "
                   "4; at most 16).");
    page += tagged(bold("LIGHTBENCH_TRANSLATE_WEBGL1"), "1: as --translate-webgl1.");

    page += ".SH EXIT STATUS\n";
    page += tagged(bold("0"), "Done: the window closed, the frame or file was written, the "
                              "program passed --check, every submission was graded (whatever "
                              "its grade).");
    page += tagged(bold("1"), "The work failed: no display, a mesh or file that could not be "
                              "read or written, a program --check or --render refused.");
    page += tagged(bold("2"), "A bad command line, with one line naming the option: an "
                              "unknown option, a bad value, a scene, lesson or exercise that "
                              "cannot be used; with --grade, a submission that could not be "
                              "read (the others are graded).");
    page += tagged(bold("129") + ", " + bold("130") + ", " + bold("143"),
                   "--grade stopped by SIGHUP, SIGINT or SIGTERM; the submissions that "
                   "finished keep their lines and report rows.");

    page += ".SH EXAMPLES\n";
    // The headless ones under Xvfb with a 24-bit screen: OpenGL needs it (README). -noreset:
    // the server's reset after lightbench exits can make xvfb-run exit 5, not with our status.
    const QString xvfb = "xvfb-run -a -s \"-screen 0 1920x1080x24 -noreset\" \\\n    ";
    const std::pair<QString, QString> examples[] = {
        {"Open a lesson in the window, at its first step:", "lightbench lecture.lblesson"},
        {"Open a scene with Gouraud shading instead of the scene's own:",
         "lightbench --scene phong.lbscene --shading gouraud"},
        {"Draw a torus lit per vertex into a PNG, without a window:",
         xvfb + "lightbench --render torus.png --shape torus --shading gouraud"},
        {"Print what the GPU and the CPU reference give for one pixel:",
         xvfb + "lightbench --probe 400,300"},
        {"Check your shaders: compile, link and try them:",
         xvfb + "lightbench --check --vertex my.vert --fragment my.frag"},
        {"Grade a class against an exercise, with a CSV report:",
         xvfb + "lightbench --grade submissions/* --exercise exercise.json --report grades.csv"}};
    for (const auto &[what, command] : examples)
        page += ".PP\n" + text(what) + ".nf\n.RS 4\n" + text(command) + ".RE\n.fi\n";

    page += ".SH SEE ALSO\n" + bold("xvfb-run") + "(1)\n";
    return page;
}

} // namespace lb
