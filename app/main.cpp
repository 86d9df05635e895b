// lightbench: the window (with FILE... opened in it), or one of the command line's runs
// (--render, --probe, --plot, --check, --grade, ...). This file picks one; the window lives in
// window/ (runWindow), the command line's runs in cli/ (runCommandLine).

#include "command_line.h"
#include "grade.h"
#include "message_text.h"
#include "offscreen.h"
#include "run_command_line.h"
#include "run_window.h"
#include "safe_write.h"
#include "standard_output.h"
#include "standard_streams.h"
#include "webgl1_translation.h"

#include <QCoreApplication>
#include <QGuiApplication>

#include <cstdio>

namespace {

bool haveDisplay()
{
    return !qEnvironmentVariableIsEmpty("DISPLAY") ||
           !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
           !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

QStringList rawArguments(int argc, char **argv)
{
    QStringList args;
    for (int i = 0; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    return args;
}

} // namespace

int main(int argc, char **argv)
{
    // Before anything opens a file or a socket: a closed 0, 1 or 2 is opened on /dev/null,
    // and a result asked for on a stdout that was closed is an error, not lost.
    lb::setStandardOutputWasClosed(lb::platform::reopenClosedStandardStreams() & 2u);
    lb::reportFileSizeLimitAsError(); // `ulimit -f`: a message and an exit code, not a kill
    // The command line is checked before Qt starts, so a bad one answers even with no display.
    const lb::CommandLineResult parsed = lb::parseCommandLine(rawArguments(argc, argv));
    if (!parsed.commandLine) {
        if (parsed.exitCode == 0) { // --help, --version: a full disk is said
            if (const QString why = lb::writeStandardOutput(parsed.message.toLocal8Bit());
                !why.isEmpty()) {
                std::fprintf(stderr, "lightbench: %s\n", qPrintable(why));
                return 1;
            }
        } else
            std::fprintf(stderr, "lightbench: %s\n", qPrintable(parsed.message));
        return parsed.exitCode;
    }
    const lb::CommandLine &cl = *parsed.commandLine;
    lb::quietStandardErrorForGrade(cl);
    // A plot without a probed point draws no frame: no OpenGL, so no X server either.
    const bool plotOnly = cl.plot && !cl.probe;
    if (plotOnly && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (!plotOnly && !haveDisplay()) {
        if (cl.grade)
            return lb::failGrade(cl,
                                 "no display; OpenGL needs an X server (try xvfb-run -a -s "
                                 "\"-screen 0 1920x1080x24\" lightbench ...)",
                                 1);
        std::fputs("lightbench: no display; OpenGL needs an X server (try xvfb-run -a -s "
                   "\"-screen 0 1920x1080x24\" lightbench ...)\n",
                   stderr);
        return 1;
    }
    lb::setDefaultGlFormat();
    if (cl.translateWebGl1) {
        lb::setWebGl1TranslationForced(true);
        qputenv("LIGHTBENCH_TRANSLATE_WEBGL1", "1"); // the trial helper translates too
    }
    QCoreApplication::setOrganizationName("lightbench");
    QCoreApplication::setApplicationName("lightbench");
    // The installed menu entry's id: Wayland docks and task bars match the window to it.
    QGuiApplication::setDesktopFileName(QStringLiteral(LIGHTBENCH_APP_ID));

    if (!cl.sceneIgnored.isEmpty() && cl.headless()) // the window shows them in a message
        std::fprintf(stderr, "lightbench: %s: ignored: %s\n",
                     qPrintable(lb::elidedForMessage(cl.scenePath)),
                     qPrintable(lb::summarisedList(cl.sceneIgnored, "; ")));
    if (cl.headless())
        return lb::runCommandLine(argc, argv, cl);
    return lb::runWindow(argc, argv, cl);
}
