#pragma once
// The main window driven as a user drives it: a fixture that opens a fresh window on
// settings kept in a temporary file before each test, and what the feature tests share.
#include "color_edit.h"
#include "editor_panel.h"
#include "light_panel.h"
#include "load_progress.h"
#include "main_window.h"
#include "material_panel.h"
#include "mesh_actions.h"
#include "object_loader.h"
#include "object_panel.h"
#include "offscreen.h"
#include "presets.h"
#include "probe_panel.h"
#include "recent_files.h"
#include "scene_actions.h"
#include "settings_autosave.h"
#include "shader_editor.h"
#include "shading_panel.h"
#include "status_line.h"
#include "uniform_panel.h"
#include "viewport.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

#include <QImage>

#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace lb::test {

extern const QString kCube;      // a PLY file of Debian's assimp-testmodels
extern const QString kMalformed; // an OBJ that Assimp refuses

// The largest channel difference between two frames (every second pixel), 255 when their
// sizes differ.
int imageDifference(const QImage &a, const QImage &b);

#ifdef LIGHTBENCH_EXE
// The real executable with `args`, its settings in `configDir` (as XDG_CONFIG_HOME), waited
// for up to a minute, then killed. Its exit code, or -1 when it had to be killed.
inline int runLightbench(const QStringList &args, const QString &configDir,
                         QByteArray *err = nullptr)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", configDir);
    QProcess run;
    run.setProcessEnvironment(env);
    run.start(LIGHTBENCH_EXE, args);
    if (!run.waitForFinished(60000)) {
        run.kill();
        run.waitForFinished();
        return -1;
    }
    if (err)
        *err = run.readAllStandardError();
    return run.exitCode();
}
#endif

// An import helper that never answers (it sleeps ten minutes), as `dir`/slow-helper.sh, for
// the tests of a load that is cancelled or runs long; empty when it cannot be written.
QString writeSlowImportHelper(const QTemporaryDir &dir);

// Every panel dock brought forward in turn: the ones whose panel is wider than its dock (a
// horizontal scrollbar), "Light (230 px for 260)", or empty.
QString docksNeedingSideways(MainWindow &window);

class WindowTest : public QObject
{
    Q_OBJECT
protected:
    QTemporaryDir m_dir;
    std::unique_ptr<QSettings> m_settings;
    std::unique_ptr<MainWindow> m_window;

    const Scene &scene() { return m_window->document().scene(); }
    QImage frame();
    // Runs `change` and checks that the viewport's image changed with it.
    template <typename F> void expectNewImage(F &&change, const char *what)
    {
        const QImage before = frame();
        change();
        const QImage after = frame();
        QVERIFY2(imageDifference(before, after) > 10, what);
    }
    // Opens a mesh as File > Open Mesh does; returns what the loader said.
    std::pair<bool, QString> openMesh(const QString &path);
    // Waits for the window to settle, runs `action` and waits for the viewport's next
    // programBuilt() signal (10 s at most), then for the window to settle again; returns that
    // build, or nothing when none came.
    std::optional<ProgramBuild> buildAfter(const std::function<void()> &action);

protected slots:
    void init();
    void cleanup() { m_window.reset(); }
};

// main() for one feature's tests: the GL format first, then a QApplication.
int runWindowTest(WindowTest &test, int argc, char **argv);

} // namespace lb::test

#define LB_WINDOW_TEST_MAIN(Class)                                                                 \
    int main(int argc, char **argv)                                                                \
    {                                                                                              \
        Class test;                                                                                \
        return lb::test::runWindowTest(test, argc, argv);                                          \
    }
