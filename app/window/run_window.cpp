#include "run_window.h"

#include "edit_bench.h"
#include "file_arguments.h"
#include "language.h"
#include "language_menu.h"
#include "lesson_actions.h"
#include "main_window.h"
#include "mesh_actions.h"
#include "object_loader.h"
#include "safe_write.h"
#include "scene_actions.h"
#include "settings_autosave.h"
#include "settings_store.h"
#include "shader_document.h"
#include "stop_signals.h"
#include "unsaved_work.h"
#include "viewport.h"

#include <QApplication>
#include <QIcon>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>

#include <cstdio>

namespace lb {

int runWindow(int &argc, char **argv, const CommandLine &cl)
{
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
    SettingsStore store(QSettings().fileName());
    if (!store.error().isEmpty())
        std::fprintf(stderr, "lightbench: settings: %s\n", qPrintable(store.error()));
    QSettings &settings = store.settings();
    // The window's words: View > Language, else LANG (language.h); before the window reads them.
    installTranslators(app, resolvedLanguage(cl.language.value_or(
                                settings.value(kInterfaceLanguageKey).toString())));
    MainWindow window(settings);
    window.autosave()->setWriteThrough(store.fileName(), [&store] { return store.save(); });
    // What is set after the window's last save (QSettings used to write it as it went).
    const auto exitSaved = [&store](int status) {
        if (const QString error = store.save(); !error.isEmpty())
            std::fprintf(stderr, "lightbench: settings not saved: %s\n", qPrintable(error));
        return status;
    };
    if (cl.importMemoryMB || cl.importSeconds) {
        ImportLimits limits = window.objectLoader()->limits();
        limits.memoryMB = cl.importMemoryMB.value_or(limits.memoryMB);
        limits.seconds = cl.importSeconds.value_or(limits.seconds);
        window.meshActions()->setSessionLimits(limits);
    }
    // Someone is there to answer: quit, close, another scene (FILE... included) and Reset
    // Everything ask Save / Discard / Cancel before unsaved work is set aside. A scripted run
    // (--screenshot, --bench-edits) has no one to answer and must never wait: it never asks.
    if (cl.screenshotPath.isEmpty() && cl.benchEdits == 0)
        window.setUnsavedWorkAsker(askAboutUnsavedWork);
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
        openFileArguments(window, cl.filePaths);
    Scene scene = window.document().scene();
    cl.applyTo(scene);
    window.document().set(scene);
    if (cl.benchEdits > 0) {
        window.show();
        QTimer::singleShot(500, &window, [&] {
            QCoreApplication::exit(
                runEditBench(window, cl.benchEdits, cl.vertexSource, cl.fragmentSource));
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
            if (const QString error = writeImageSafely(path, window.grab().toImage());
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
    // A logout or `kill` (SIGTERM, SIGHUP) or Ctrl+C in the terminal is a quit with nobody to
    // ask: the settings and the session are saved as at a close, unsaved work kept in the
    // session (it comes back at the next start), the settings' scratch folder removed. It
    // used to end the process where it stood: nothing saved, the scratch folder left in TMPDIR.
    StopSignals stops;
    QObject::connect(&stops, &StopSignals::stopRequested, &window, [&window](int signal) {
        window.setUnsavedWorkAsker({});
        window.close();
        QCoreApplication::exit(StopSignals::exitCodeFor(signal));
    });
    const int status = exitSaved(app.exec());
    // View > Language's restart: after the settings are saved, so the new one reads them.
    if (restartRequested() && !restartApplication()) {
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

} // namespace lb
