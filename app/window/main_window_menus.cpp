// MainWindow's menus: files, edit, shading, view (camera, probe, zoom, presentation, scale,
// docks) and help.
#include "main_window.h"

#include "language_menu.h"

#include "editor_panel.h"
#include "help.h"
#include "lesson_actions.h"
#include "main_window_settings.h"
#include "mesh_actions.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "shading_panel.h"
#include "status_line.h"
#include "viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>

namespace lb {

using namespace window_settings;

void MainWindow::buildMenus()
{
    auto addItem = [this](QMenu *menu, const QString &text, const QKeySequence &key, auto slot) {
        QAction *action = menu->addAction(text);
        action->setShortcut(key);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };

    QMenu *file = menuBar()->addMenu(tr("&File"));
    m_sceneActions->addToMenu(file);
    m_lessons->addToMenu(file);
    file->addSeparator();
    m_checkAction =
        addItem(file, tr("Chec&k My Work"), QKeySequence(tr("F9")), [this] { checkWork(); });
    m_checkAction->setEnabled(m_sceneActions->exercise() &&
                              m_sceneActions->exercise()->unread.isUndefined());
    addItem(file, tr("Side B: Shader Files..."), QKeySequence(), [this] { chooseSideBFiles(); });
    file->addSeparator();
    const QString filter = tr("Shader pairs (*.vert *.frag);;All files (*)");
    auto report = [this](const QString &error) {
        if (!error.isEmpty())
            QMessageBox::warning(this, tr("Shader files"), error);
    };
    // The scene (with its shaders inline) has Ctrl+O / Ctrl+S; shader files their own keys.
    addItem(file, tr("Open S&haders..."), QKeySequence(tr("Ctrl+Shift+O")), [this, filter, report] {
        const QStringList paths = QFileDialog::getOpenFileNames(
            this, tr("Open a shader pair (NAME.vert and NAME.frag)"), {}, filter);
        if (!paths.isEmpty())
            report(m_shaders.openFiles(paths));
    });
    addItem(file, tr("Save Shaders"), QKeySequence(tr("Ctrl+Alt+S")), [this] { saveShaders(); });
    addItem(file, tr("Save Shaders As..."), QKeySequence(), [this] { saveShadersAs(); });
    file->addSeparator();
    QMenu *edit = new QMenu(tr("&Edit"), this); // filled below, shown after File
    //: the menu (camera, probe, zoom, presentation, docks), not the 3D view itself
    QMenu *view = new QMenu(tr("&View"), this);
    m_meshActions->addToMenus(file, edit, view);
    file->addSeparator();
    addItem(file, tr("Reset &Everything"), QKeySequence(tr("Ctrl+Shift+R")),
            [this] { resetEverything(); });
    file->addSeparator();
    addItem(file, tr("&Quit"), QKeySequence::Quit, [this] { close(); });
    menuBar()->addMenu(edit);
    // The editor's keys from anywhere in the window (in the editor, it takes them itself).
    edit->addSeparator();
    addItem(edit, tr("&Undo in the Editor"), QKeySequence::Undo, [this] { m_editor->undo(); });
    QAction *redo = addItem(edit, tr("&Redo in the Editor"), QKeySequence(tr("Ctrl+Y")),
                            [this] { m_editor->redo(); });
    redo->setShortcuts({QKeySequence(tr("Ctrl+Y")), QKeySequence(tr("Ctrl+Shift+Z"))});
    addItem(edit, tr("&Find in the Shader"), QKeySequence::Find, [this] { m_editor->startFind(); });

    QMenu *shading = menuBar()->addMenu(tr("&Shading"));
    // A choice the program on screen does not follow is greyed in the panel with why; its
    // key then says why instead of changing what does not draw.
    addItem(shading, tr("Toggle &Gouraud / Phong"), QKeySequence(tr("G", "shortcut")), [this] {
        if (!m_shading->shadingCombo()->isEnabled()) {
            m_status->showMessage(m_shading->shadingCombo()->toolTip());
            return;
        }
        m_document.edit([](Scene &s) {
            s.shading.shading =
                s.shading.shading == Shading::Phong ? Shading::Gouraud : Shading::Phong;
        });
    });
    // Ctrl+B, not B: a clicker's "blank screen" key is B (blankPressed()).
    addItem(
        shading, tr("Toggle Phong / &Blinn-Phong specular"), QKeySequence(tr("Ctrl+B")), [this] {
            if (m_shaders.fixedModel().specular) {
                m_status->showMessage(tr("The program in the editor (%1) computes its own specular "
                                         "term: load a preset or Reset Everything to switch it.")
                                          .arg(m_editor->programName()));
                return;
            }
            if (!m_shading->specularCombo()->isEnabled()) { // the program reads no uSpecularModel
                m_status->showMessage(m_shading->specularCombo()->toolTip());
                return;
            }
            m_document.edit(
                [](Scene &s) { s.shading.specular = nextSpecularModel(s.shading.specular); });
        });
    addItem(shading, tr("Toggle &Perspective / Orthographic"), QKeySequence(tr("P", "shortcut")),
            [this] {
                m_document.edit([](Scene &s) {
                    s.shading.projection = s.shading.projection == Projection::Perspective
                                               ? Projection::Orthographic
                                               : Projection::Perspective;
                });
            });
    addItem(shading, tr("Toggle &Lighting"), QKeySequence(tr("L", "shortcut")), [this] {
        m_document.edit([](Scene &s) { s.shading.lighting = !s.shading.lighting; });
    });
    // The model taken apart: each term on or off (the built-in programs and any program that
    // reads uEnableAmbient, uEnableDiffuse, uEnableSpecular).
    const std::pair<QString, bool TermSwitches::*> terms[] = {
        {tr("Toggle the &Ambient Term"), &TermSwitches::ambient},
        {tr("Toggle the &Diffuse Term"), &TermSwitches::diffuse},
        {tr("Toggle the &Specular Term"), &TermSwitches::specular}};
    // Their initials: a translation may give them its own.
    struct Key
    {
        const char *source, *disambiguation;
    };
    const Key termKeys[] = {QT_TRANSLATE_NOOP3("lb::MainWindow", "A", "shortcut"),
                            QT_TRANSLATE_NOOP3("lb::MainWindow", "D", "shortcut"),
                            QT_TRANSLATE_NOOP3("lb::MainWindow", "S", "shortcut")};
    for (int i = 0; i < 3; ++i)
        addItem(shading, terms[i].first,
                QKeySequence(tr(termKeys[i].source, termKeys[i].disambiguation)),
                [this, member = terms[i].second] {
                    m_document.edit(
                        [&](Scene &s) { s.shading.terms.*member = !(s.shading.terms.*member); });
                });
    addItem(shading, tr("&Compare: Off / Side by Side / Wipe / Difference"),
            QKeySequence(tr("C", "shortcut")), [this] {
                m_document.edit(
                    [](Scene &s) { s.compare.mode = CompareMode((int(s.compare.mode) + 1) % 4); });
            });

    menuBar()->addMenu(view);
    addItem(view, tr("&Reset Camera"), QKeySequence(tr("R", "shortcut")),
            [this] { m_viewport->resetCamera(); });
    addItem(view, tr("Clear the &Probe (in Presentation Mode: Leave It)"), QKeySequence(tr("Esc")),
            [this] { escapePressed(); });
    addItem(view, tr("&Auto-rotate"), QKeySequence(tr("Space")), [this] {
        m_document.edit([](Scene &s) {
            bool &turning = s.selectedObject().autoRotate;
            turning = !turning;
        });
    });
    addViewMenu(view);

    menuBar()->addMenu(m_lessons->lessonMenu());
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    addItem(help, tr("&Keyboard Shortcuts"), QKeySequence::HelpContents,
            [this] { showShortcuts(this, menuBar()); });
    addItem(help, tr("&Features (README)"), QKeySequence(), [this] { showFeatures(this); });
    addItem(help, tr("&About lightbench"), QKeySequence(), [this] { showAbout(this, m_glInfo); });
}

void MainWindow::addViewMenu(QMenu *view)
{
    view->addSeparator();
    // Window shortcuts: the editor no longer binds these keys (it typed "=" and "+").
    QAction *zoomIn = view->addAction(tr("Zoom &In Editor"), this,
                                      [this] { m_editor->setZoom(m_editor->zoom() + 1); });
    zoomIn->setShortcuts({QKeySequence::ZoomIn, QKeySequence(tr("Ctrl+="))});
    QAction *zoomOut = view->addAction(tr("Zoom &Out Editor"), this,
                                       [this] { m_editor->setZoom(m_editor->zoom() - 1); });
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    QAction *zoomReset =
        view->addAction(tr("Reset Editor &Zoom"), this, [this] { m_editor->setZoom(0); });
    zoomReset->setShortcut(QKeySequence(tr("Ctrl+0")));

    view->addSeparator();
    addPresentationActions(view);
    QMenu *scale = view->addMenu(tr("UI &Scale"));
    m_scaleGroup = new QActionGroup(this);
    for (int percent : kScalePercents) {
        //: View > UI Scale: a size in percent ("125%")
        QAction *a = scale->addAction(tr("%1%").arg(percent), this,
                                      [this, percent] { setUiScale(percent / 100.0); });
        a->setCheckable(true);
        a->setData(percent);
        m_scaleGroup->addAction(a);
    }
    applyScale(); // checks the current one
    addLanguageMenu(view, m_settings, this);
    view->addAction(tr("Fit the &Window to the Screen"), this, [this] {
        if (m_presentation)
            setPresentation(false);
        if (const QScreen *s = screen())
            fitToScreen(s->availableGeometry());
    });

    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());
}

} // namespace lb
