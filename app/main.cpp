// lightbench: the window (with FILE... opened in it), or one headless frame (--render /
// --probe / --bench-frames).

#include "catalogue.h"
#include "command_line.h"
#include "edit_bench.h"
#include "file_arguments.h"
#include "grade.h"
#include "headless.h"
#include "language.h"
#include "lesson_actions.h"
#include "main_window.h"
#include "mesh_actions.h"
#include "message_text.h"
#include "object_loader.h"
#include "offscreen.h"
#include "plot_output.h"
#include "safe_write.h"
#include "scene_actions.h"
#include "settings_autosave.h"
#include "settings_store.h"
#include "shader_document.h"
#include "unsaved_work.h"
#include "viewport.h"
#include "webgl1_translation.h"

#include <QApplication>
#include <QGuiApplication>
#include <QIcon>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>

#include <cstdio>
#include <memory>
#include <new>

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
    lb::reportFileSizeLimitAsError(); // `ulimit -f`: a message and an exit code, not a kill
    // The command line is checked before Qt starts, so a bad one answers even with no display.
    const lb::CommandLineResult parsed = lb::parseCommandLine(rawArguments(argc, argv));
    if (!parsed.commandLine) {
        if (parsed.exitCode == 0) { // --help, --version: a full disk is said
            std::fputs(qPrintable(parsed.message), stdout);
            if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
                std::fputs("lightbench: could not write to standard output\n", stderr);
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
    if (cl.headless()) {
        // A plot's chart is a graphics-view widget: it needs QApplication; a frame does not.
        std::unique_ptr<QGuiApplication> application =
            cl.plot ? std::make_unique<QApplication>(argc, argv)
                    : std::make_unique<QGuiApplication>(argc, argv);
        QGuiApplication &app = *application;
        if (cl.grade)
            return lb::runGrade(cl);
        if (!cl.gradeOne.isEmpty()) {
            lb::installCatalogueFromWindow(app); // Check My Work's reasons in its language
            return lb::runGradeOne(cl);
        }
        // Headless frames start from the scene file or the defaults, not the saved session.
        const lb::Scene scene = cl.headlessScene();
        if (!cl.saveScenePath.isEmpty()) {
            const QString error = lb::writeSceneFile(
                cl.saveScenePath,
                lb::SceneFile{scene, cl.program(),
                              cl.sceneFile ? cl.sceneFile->exercise : std::nullopt});
            if (!error.isEmpty()) {
                std::fprintf(stderr, "lightbench: --save-scene: %s\n", qPrintable(error));
                return 1;
            }
            if (cl.renderPath.isEmpty() && !cl.probe && !cl.plot && cl.benchFrames == 0 &&
                !cl.check)
                return 0;
        }
        if (cl.plot && cl.language) // a slide's words in the language asked for
            lb::installCatalogue(app, lb::resolvedLanguage(*cl.language));
        if (plotOnly) // the curves alone: no mesh, no OpenGL
            return lb::writePlotOutputs(cl, scene, nullptr);
        try {
            return lb::runHeadless(cl, scene);
        } catch (const std::bad_alloc &e) { // within the scene budget, this is rare
            const bool mesh = dynamic_cast<const lb::ObjectMeshOutOfMemory *>(&e);
            std::fprintf(stderr, "lightbench: %s\n",
                         mesh ? e.what() : "out of memory"); // "... building the torus at ..."
            return 1;
        }
    }

    // Numbers are written the English way in every language, 1.80 as the probe, the
    // equation and the shaders write them, whatever LANG says; the number boxes read a point
    // and a comma alike (number_box.h). Machine output never depends on it: the headless runs
    // above keep the system's locale, and write numbers with QString::number and JSON.
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    QApplication app(argc, argv);
    QIcon icon;
    for (const int size : {64, 256})
        icon.addFile(QString(":/icons/%1-%2.png").arg(LIGHTBENCH_APP_ID).arg(size));
    QApplication::setWindowIcon(icon);
    // The settings file is written whole or not at all (settings_store.h).
    lb::SettingsStore store(QSettings().fileName());
    if (!store.error().isEmpty())
        std::fprintf(stderr, "lightbench: settings: %s\n", qPrintable(store.error()));
    QSettings &settings = store.settings();
    // The window's words: View > Language, else LANG (language.h); before the window reads them.
    lb::installTranslators(app, lb::resolvedLanguage(cl.language.value_or(
                                    settings.value(lb::kInterfaceLanguageKey).toString())));
    lb::MainWindow window(settings);
    window.autosave()->setWriteThrough(store.fileName(), [&store] { return store.save(); });
    // What is set after the window's last save (QSettings used to write it as it went).
    const auto exitSaved = [&store](int status) {
        if (const QString error = store.save(); !error.isEmpty())
            std::fprintf(stderr, "lightbench: settings not saved: %s\n", qPrintable(error));
        return status;
    };
    if (cl.importMemoryMB || cl.importSeconds) {
        lb::ImportLimits limits = window.objectLoader()->limits();
        limits.memoryMB = cl.importMemoryMB.value_or(limits.memoryMB);
        limits.seconds = cl.importSeconds.value_or(limits.seconds);
        window.meshActions()->setSessionLimits(limits);
    }
    // Someone is there to answer: quit, close, another scene (FILE... included) and Reset
    // Everything ask Save / Discard / Cancel before unsaved work is set aside. A scripted run
    // (--screenshot, --bench-edits) has no one to answer and must never wait: it never asks.
    if (cl.screenshotPath.isEmpty() && cl.benchEdits == 0)
        window.setUnsavedWorkAsker(lb::askAboutUnsavedWork);
    // A scene file opens as File > Open Scene would (its message included), a lesson as File
    // > Open Lesson would, at its step; the options given beside them apply on top. FILE...
    // (the desktop's) open the same way, asking first about the last session's unsaved work
    // (a double-clicked file must not set it aside unasked), and one that cannot be opened is
    // said in the window.
    if (!cl.lessonPath.isEmpty())
        window.lessonActions()->open(cl.lessonPath, cl.lessonStep - 1);
    else if (!cl.scenePath.isEmpty()) {
        window.lessonActions()->closeLesson(); // the last session's: a scene was asked for
        window.sceneActions()->open(cl.scenePath);
    } else if (!cl.filePaths.isEmpty())
        lb::openFileArguments(window, cl.filePaths);
    lb::Scene scene = window.document().scene();
    cl.applyTo(scene);
    window.document().set(scene);
    if (cl.benchEdits > 0) {
        window.show();
        QTimer::singleShot(500, &window, [&] {
            QCoreApplication::exit(
                lb::runEditBench(window, cl.benchEdits, cl.vertexSource, cl.fragmentSource));
        });
        return exitSaved(app.exec());
    }
    if (cl.hasUserProgram() && !cl.programFromScene) // opened as File > Open Shaders would
        window.shaderDocument().openFiles({cl.vertexPath, cl.fragmentPath});
    window.show();
    if (cl.presentation)
        window.setPresentation(true);
    if (cl.uiScalePercent)
        window.setUiScale(*cl.uiScalePercent / 100.0);

    if (!cl.screenshotPath.isEmpty()) {
        // Grab once the viewport has drawn, the mesh is in and the window has settled, then
        // quit.
        auto *settle = new QTimer(&window);
        settle->setInterval(700);
        QObject::connect(
            window.viewport(), &QOpenGLWidget::frameSwapped, settle, [settle] { settle->start(); },
            Qt::SingleShotConnection);
        QObject::connect(settle, &QTimer::timeout, &window, [&, settle] {
            if (!window.isSettled())
                return; // the timer fires again (a program being tried draws once accepted)
            settle->stop();
            const QString path = cl.screenshotPath;
            if (const QString error = lb::writeImageSafely(path, window.grab().toImage());
                !error.isEmpty()) {
                std::fprintf(stderr, "lightbench: --screenshot: cannot write %s\n",
                             qPrintable(error));
                QCoreApplication::exit(1);
                return;
            }
            std::printf("%s\n", qPrintable(path));
            std::fflush(stdout);
            window.close();
        });
    }
    const int status = exitSaved(app.exec());
    // View > Language's restart: after the settings are saved, so the new one reads them.
    if (lb::restartRequested() && !lb::restartApplication()) {
        std::fputs("lightbench: could not start again; start it yourself to see the new "
                   "language\n",
                   stderr);
        QMessageBox::warning(nullptr, QCoreApplication::translate("lb::Language", "Language"),
                             QCoreApplication::translate(
                                 "lb::Language", "lightbench could not start again. Start it "
                                                 "yourself to see the new language."));
    }
    return status;
}
