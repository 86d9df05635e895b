#include "main_window.h"

#include "editor_panel.h"
#include "help.h"
#include "light_panel.h"
#include "material_panel.h"
#include "mesh_actions.h"
#include "object_loader.h"
#include "object_panel.h"
#include "presets.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "shading_panel.h"
#include "status_line.h"
#include "uniform_panel.h"
#include "viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QJsonDocument>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
// 2: the editor dock, 3: the probe dock, 4: the layouts fitted to the screen
constexpr int kStateVersion = 4;
const char *kSceneKey = "scene";
const char *kGeometryKey = "window/geometry";
const char *kStateKey = "window/state";
const char *kScreenKey = "window/screen"; // the available size the state was kept on
const char *kLayoutKey = "window/layout";
const char *kScaleKey = "ui/scale";
const char *kPresentationScaleKey = "ui/presentationScale";
constexpr int kScalePercents[] = {100, 125, 150, 175, 200, 250};
} // namespace

MainWindow::MainWindow(QSettings &settings, QWidget *parent)
    : QMainWindow(parent), m_settings(settings)
{
    const QByteArray savedScene = m_settings.value(kSceneKey).toByteArray();
    if (!savedScene.isEmpty())
        m_document.set(Scene::fromJson(QJsonDocument::fromJson(savedScene).object()));
    m_scale = clampUiScale(m_settings.value(kScaleKey, 1.0).toDouble());
    m_presentationScale = clampUiScale(m_settings.value(kPresentationScaleKey, 1.75).toDouble());
    applyUiScale(m_scale); // before the widgets, which size themselves by the font

    m_viewport = new Viewport(&m_document, this);
    setCentralWidget(m_viewport);
    m_loader = new ObjectLoader(&m_document, this);
    connect(m_loader, &ObjectLoader::meshReady, m_viewport, &Viewport::setObject);
    m_viewport->setObject(m_loader->mesh(), m_loader->texture());
    m_light = new LightPanel(&m_document);
    m_material = new MaterialPanel(&m_document);
    m_shading = new ShadingPanel(&m_document);
    m_object = new ObjectPanel(&m_document);
    m_uniforms = new UniformPanel(&m_document);
    m_probe = new ProbePanel(&m_document, m_viewport);
    addPanelDock(tr("Light"), "lightDock", m_light);
    addPanelDock(tr("Material"), "materialDock", m_material);
    addPanelDock(tr("Shading"), "shadingDock", m_shading);
    addPanelDock(tr("Object"), "objectDock", m_object);
    addPanelDock(tr("Uniforms"), "uniformDock", m_uniforms);
    QDockWidget *probeDock = addPanelDock(tr("Probe"), "probeDock", m_probe);
    connect(m_viewport, &Viewport::probeRequested, this, [this, probeDock](QPoint pixel) {
        m_probe->probeAt(pixel);
        probeDock->show();
        probeDock->raise();
    });

    m_editor = new EditorPanel(&m_shaders);
    m_editorDock = new QDockWidget(tr("Shader editor"), this);
    m_editorDock->setObjectName("editorDock");
    m_editorDock->setWidget(m_editor);
    addDockWidget(Qt::RightDockWidgetArea, m_editorDock);
    connect(m_editor, &EditorPanel::compileRequested, m_viewport, &Viewport::compileProgram);
    connect(m_viewport, &Viewport::programBuilt, m_editor, &EditorPanel::showBuild);
    connect(m_viewport, &Viewport::programBuilt, this, &MainWindow::showProgramUsage);

    // The status line's fixed places exist before anything reports to them.
    m_status = new StatusLine(statusBar());
    statusBar()->addPermanentWidget(m_status, 1);
    connect(m_viewport, &Viewport::glInfo, this, [this](const QString &info) {
        m_glInfo = info;
        m_status->driverLabel()->setText(info);
    });

    if (!m_editor->restoreState(m_settings))
        m_editor->loadPreset(builtInPreset(m_document.scene().shading.shading == Shading::Gouraud));
    m_editor->setUiScale(m_scale);
    connect(&m_shaders, &ShaderDocument::changed, this, [this] {
        syncShadingWithProgram();
        updateStatus();
        updateTitle();
        if (!m_saveTimer.isActive())
            m_saveTimer.start();
    });

    m_meshActions = new MeshActions(this, &m_document, m_loader, m_settings, m_status);
    connect(m_meshActions, &MeshActions::shaderFilesDropped, this,
            [this](const QStringList &paths) {
                if (const QString error = m_shaders.openFiles(paths); !error.isEmpty())
                    QMessageBox::warning(this, tr("Shader files"), error);
            });
    m_sceneActions = new SceneActions(this, &m_document, &m_shaders, m_viewport, m_settings);
    connect(m_meshActions, &MeshActions::sceneFileDropped, m_sceneActions, &SceneActions::open);
    connect(m_sceneActions, &SceneActions::documentChanged, this, &MainWindow::updateTitle);
    connect(m_sceneActions, &SceneActions::sceneOpened, m_probe, &ProbePanel::clear);
    connect(m_object, &ObjectPanel::openMeshRequested, m_meshActions, &MeshActions::showOpenDialog);
    connect(m_object, &ObjectPanel::adoptFileMaterialRequested, m_loader,
            &ObjectLoader::setAdoptFileMaterial);
    buildMenus();

    // The screen decides the first size and the layout; a saved window comes back only
    // where it still fits (a laptop's window on a projector does not).
    const QScreen *screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
    const QRect available = screen ? screen->availableGeometry() : QRect(0, 0, 1280, 720);
    fitToScreen(available);
    // The window as it was, only on a screen of the same size: one kept on a laptop does not
    // come back on a projector (Qt would move it, but keep the laptop's docks).
    if (m_settings.value(kScreenKey).toSize() == available.size() &&
        restoreGeometry(m_settings.value(kGeometryKey).toByteArray())) {
        m_layout = DockLayout(std::clamp(m_settings.value(kLayoutKey, 0).toInt(), 0, 1));
        if (restoreState(m_settings.value(kStateKey).toByteArray(), kStateVersion))
            m_widthsPending = false; // the user's own dock sizes
        applyTabPositions();
    }

    m_saveTimer.setSingleShot(true);
    m_saveTimer.setInterval(500);
    connect(&m_saveTimer, &QTimer::timeout, this, &MainWindow::saveSettings);
    connect(&m_document, &SceneDocument::changed, this, [this](SceneParts parts) {
        updateStatus();
        updateTitle();
        if (parts & ScenePart::Shading) {
            m_shaders.followShading(m_document.scene().shading.shading == Shading::Gouraud);
            syncShadingWithProgram(); // a reset or an option cannot unfix a fixed model
        }
        // Not restarted on every change: auto-rotate edits the scene 60 times a second,
        // and a timer restarted that often would never fire.
        if (!m_saveTimer.isActive())
            m_saveTimer.start();
    });
    syncShadingWithProgram();
    updateStatus();
    updateTitle();
    if (m_editor->restoredUnsavedEdits())
        m_status->showMessage(tr("Unsaved shader edits from the last session were restored"),
                              20000);
}

QDockWidget *MainWindow::addPanelDock(const QString &title, const QString &objectName,
                                      QWidget *panel)
{
    // Narrow docks put a form's field under its label instead of scrolling sideways.
    for (QFormLayout *form : panel->findChildren<QFormLayout *>())
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto *scroll = new QScrollArea; // a dock whose panel scrolls when the screen is too short
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *dock = new QDockWidget(title, this);
    dock->setObjectName(objectName); // saveState() needs it
    dock->setWidget(scroll);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    m_panelDocks.push_back(dock);
    return dock;
}

void MainWindow::fitToScreen(const QRect &available)
{
    m_available = available;
    const bool wasLarge = isFullScreen() || isMaximized();
    if (wasLarge)
        showNormal();
    setGeometry(initialGeometry(available));
    if (wasLarge) // the window manager answers showNormal() with its own geometry later
        QTimer::singleShot(0, this, [this] { setGeometry(initialGeometry(m_available)); });
    arrangeDocks(dockLayoutFor(available.width()));
}

void MainWindow::keepInsideScreen()
{
    // setGeometry() places the inside of the window; a window manager's frame comes on top.
    // Once the frame is known, the whole window shrinks into the available area.
    if (isFullScreen() || isMaximized() || m_available.isEmpty())
        return;
    const QRect frame = frameGeometry();
    if (m_available.contains(frame))
        return;
    const QSize margins = frame.size() - geometry().size();
    const QRect inside =
        initialGeometry(m_available, size().boundedTo(m_available.size() - margins));
    resize(inside.size());
    move(inside.topLeft() - QPoint(margins.width() / 2, 0));
}

void MainWindow::arrangeDocks(DockLayout layout)
{
    m_layout = layout;
    for (QDockWidget *dock : m_panelDocks) {
        dock->setFloating(false);
        removeDockWidget(dock);
    }
    removeDockWidget(m_editorDock);
    m_editorDock->setFloating(false);
    QDockWidget *light = m_panelDocks[0];
    QDockWidget *shading = m_panelDocks[2];
    addDockWidget(Qt::RightDockWidgetArea, m_editorDock);
    if (layout == DockLayout::Wide) {
        // Light over Material over the rest as tabs: the two most used panels open at once.
        addDockWidget(Qt::LeftDockWidgetArea, light);
        addDockWidget(Qt::LeftDockWidgetArea, m_panelDocks[1], Qt::Vertical);
        addDockWidget(Qt::LeftDockWidgetArea, shading, Qt::Vertical);
        for (std::size_t i = 3; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(shading, m_panelDocks[i]);
    } else if (layout == DockLayout::Compact || !presentationIsShort()) {
        // Compact: one column of tabs down the left edge, whose names stay whole. Presentation:
        // the same tabs under the editor, so the view keeps the whole left and the panels
        // get the editor's width (they need it at a big scale).
        addDockWidget(layout == DockLayout::Compact ? Qt::LeftDockWidgetArea
                                                    : Qt::RightDockWidgetArea,
                      light, Qt::Vertical);
        for (std::size_t i = 1; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(light, m_panelDocks[i]);
    } else {
        // Presentation on a short screen (a 720-line projector): the panels are tabs beside
        // the editor, each with the whole height, rather than a strip of three rows under it.
        tabifyDockWidget(m_editorDock, light);
        for (std::size_t i = 1; i < m_panelDocks.size(); ++i)
            tabifyDockWidget(light, m_panelDocks[i]);
    }
    applyTabPositions();
    for (QDockWidget *dock : m_panelDocks)
        dock->show();
    m_editorDock->show();
    (layout == DockLayout::Wide                                    ? shading
     : layout == DockLayout::Presentation && presentationIsShort() ? m_editorDock
                                                                   : light)
        ->raise();
    applyDockWidths();
    // The docks' tab bars exist once the layout has run: names whole, scrolled when short.
    QTimer::singleShot(0, this, [this] {
        for (QTabBar *bar : findChildren<QTabBar *>(Qt::FindDirectChildrenOnly)) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    });
}

bool MainWindow::presentationIsShort() const
{
    return height() < 900; // full screen: the screen's height
}

void MainWindow::applyTabPositions()
{
    setTabPosition(Qt::LeftDockWidgetArea,
                   m_layout == DockLayout::Compact ? QTabWidget::West : QTabWidget::North);
    setTabPosition(Qt::RightDockWidgetArea, QTabWidget::North);
}

void MainWindow::applyDockWidths()
{
    // Before the window is shown its layout has no size to share out: the widths wait.
    if (!isVisible()) {
        m_widthsPending = true;
        return;
    }
    m_widthsPending = false;
    const int w = width();
    const DockWidths shares = dockWidths(m_layout, w);
    if (m_layout == DockLayout::Presentation) {
        // The editor over the panels on the right; the view has the rest of the width.
        const int h = std::max(height() - menuBar()->height() - statusBar()->height(), 100);
        resizeDocks({m_editorDock}, {shares.editor}, Qt::Horizontal);
        if (!presentationIsShort())
            resizeDocks({m_editorDock, m_panelDocks[0]}, {h * 7 / 10, h * 3 / 10}, Qt::Vertical);
        return;
    }
    // The panels get at least what their widest form needs (at this UI scale), so none
    // scrolls sideways; the editor gives way, down to 22% of the window, before the view's
    // share does.
    int need = 0;
    for (QDockWidget *dock : m_panelDocks) {
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        const QSize panel = scroll->widget()->minimumSizeHint();
        int width = panel.width() + 2 * scroll->frameWidth();
        if (panel.height() > scroll->viewport()->height())
            width += scroll->verticalScrollBar()->sizeHint().width();
        need = std::max(need, width);
    }
    if (m_layout == DockLayout::Compact) // the tab bar down the edge
        need += fontMetrics().height() + 14;
    const int panels = std::max(shares.panels, need);
    const int editor = std::max(std::min(shares.editor, int(w * 0.53) - panels), int(w * 0.22));
    resizeDocks({m_panelDocks[0], m_editorDock}, {panels, editor}, Qt::Horizontal);
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    if (m_presentation) // full screen arrives after the request
        applyDockWidths();
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    QTimer::singleShot(200, this, &MainWindow::keepInsideScreen); // the frame has come by then
    if (m_widthsPending)
        QTimer::singleShot(0, this, &MainWindow::applyDockWidths);
}

void MainWindow::setPresentation(bool on)
{
    if (on == m_presentation)
        return;
    if (on) {
        m_normalGeometry = saveGeometry();
        m_normalState = saveState(kStateVersion);
        m_normalLayout = m_layout;
        m_normalRect = geometry();
    }
    m_presentation = on;
    applyScale();
    if (on) {
        // The whole screen also where no window manager answers the full-screen request.
        if (const QScreen *s = screen())
            setGeometry(s->geometry());
        showFullScreen();
        arrangeDocks(DockLayout::Presentation);
    } else {
        showNormal();
        m_layout = m_normalLayout;
        applyTabPositions(); // not part of the saved state
        restoreState(m_normalState, kStateVersion);
        // The rectangle itself, again once the window manager has answered showNormal():
        // restoreGeometry() from full screen put the window 20 pixels low under Xvfb.
        setGeometry(m_normalRect);
        QTimer::singleShot(0, this, [this] {
            if (!m_presentation)
                setGeometry(m_normalRect);
        });
    }
    if (m_presentationAction)
        m_presentationAction->setChecked(on);
}

void MainWindow::setUiScale(double scale)
{
    (m_presentation ? m_presentationScale : m_scale) = clampUiScale(scale);
    m_settings.setValue(kScaleKey, m_scale);
    m_settings.setValue(kPresentationScaleKey, m_presentationScale);
    applyScale();
    // The panels' forms grew or shrank with the font: their widths again, once laid out.
    QTimer::singleShot(0, this, &MainWindow::applyDockWidths);
}

double MainWindow::uiScale() const
{
    return m_presentation ? m_presentationScale : m_scale;
}

void MainWindow::applyScale()
{
    const double scale = uiScale();
    applyUiScale(scale);
    m_editor->setUiScale(scale);
    if (m_scaleGroup)
        for (QAction *a : m_scaleGroup->actions())
            a->setChecked(a->data().toInt() == int(std::lround(scale * 100.0)));
}

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
    auto saveAs = [this, filter, report] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Save the shader pair as NAME.vert and NAME.frag"), {}, filter);
        if (!path.isEmpty())
            report(m_shaders.saveAs(path));
    };
    addItem(file, tr("Save Shaders"), QKeySequence(tr("Ctrl+Alt+S")), [this, saveAs, report] {
        if (m_shaders.filePath(ShaderStage::Vertex).isEmpty())
            saveAs();
        else
            report(m_shaders.save());
    });
    addItem(file, tr("Save Shaders As..."), QKeySequence(), saveAs);
    file->addSeparator();
    QMenu *edit = new QMenu(tr("&Edit"), this); // filled below, shown after File
    QMenu *view = new QMenu(tr("&View"), this);
    m_meshActions->addToMenus(file, edit, view);
    file->addSeparator();
    addItem(file, tr("Reset &Everything"), QKeySequence(tr("Ctrl+Shift+R")),
            [this] { resetEverything(); });
    file->addSeparator();
    addItem(file, tr("&Quit"), QKeySequence::Quit, [this] { close(); });
    menuBar()->addMenu(edit);

    QMenu *shading = menuBar()->addMenu(tr("&Shading"));
    addItem(shading, tr("Toggle &Gouraud / Phong"), QKeySequence(tr("G")), [this] {
        if (m_shaders.fixedModel().gouraud) { // the program's text fixes its shading
            m_status->showMessage(m_shading->shadingCombo()->toolTip());
            return;
        }
        m_document.edit([](Scene &s) {
            s.shading.shading =
                s.shading.shading == Shading::Phong ? Shading::Gouraud : Shading::Phong;
        });
    });
    addItem(shading, tr("Toggle Phong / &Blinn-Phong specular"), QKeySequence(tr("B")), [this] {
        if (m_shaders.fixedModel().blinn) {
            m_status->showMessage(tr("The program in the editor (%1) computes its own specular "
                                     "term: load a preset or Reset Everything to switch it.")
                                      .arg(m_editor->programName()));
            return;
        }
        m_document.edit([](Scene &s) {
            s.shading.specular = s.shading.specular == SpecularModel::Blinn ? SpecularModel::Phong
                                                                            : SpecularModel::Blinn;
        });
    });
    addItem(shading, tr("Toggle &Perspective / Orthographic"), QKeySequence(tr("P")), [this] {
        m_document.edit([](Scene &s) {
            s.shading.projection = s.shading.projection == Projection::Perspective
                                       ? Projection::Orthographic
                                       : Projection::Perspective;
        });
    });
    addItem(shading, tr("Toggle &Lighting"), QKeySequence(tr("L")), [this] {
        m_document.edit([](Scene &s) { s.shading.lighting = !s.shading.lighting; });
    });
    addItem(shading, tr("&Compare: Off / Side by Side / Wipe / Difference"), QKeySequence(tr("C")),
            [this] {
                m_document.edit(
                    [](Scene &s) { s.compare.mode = CompareMode((int(s.compare.mode) + 1) % 4); });
            });

    menuBar()->addMenu(view);
    addItem(view, tr("&Reset Camera"), QKeySequence(tr("R")),
            [this] { m_viewport->resetCamera(); });
    addItem(view, tr("Clear the &Probe"), QKeySequence(tr("Esc")), [this] { m_probe->clear(); });
    addItem(view, tr("&Auto-rotate"), QKeySequence(tr("Space")), [this] {
        m_document.edit([](Scene &s) { s.object.autoRotate = !s.object.autoRotate; });
    });
    addViewMenu(view);

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
    m_presentationAction =
        view->addAction(tr("&Presentation Mode"), this, [this](bool on) { setPresentation(on); });
    m_presentationAction->setCheckable(true);
    m_presentationAction->setShortcut(QKeySequence(tr("F11")));
    m_presentationAction->setToolTip(
        tr("Full screen, the presentation UI scale, the view and the editor large"));
    QMenu *scale = view->addMenu(tr("UI &Scale"));
    m_scaleGroup = new QActionGroup(this);
    for (int percent : kScalePercents) {
        QAction *a = scale->addAction(tr("%1%").arg(percent), this,
                                      [this, percent] { setUiScale(percent / 100.0); });
        a->setCheckable(true);
        a->setData(percent);
        m_scaleGroup->addAction(a);
    }
    applyScale(); // checks the current one
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

void MainWindow::resetEverything()
{
    m_sceneActions->forgetFile(); // Ctrl+S must not write the defaults over the file
    // The editor first (undoable there): while an edited program still drew, the scene's
    // shading would be held to that program's.
    const bool hadEdits = !m_shaders.showsBuiltIn();
    m_shaders.loadPreset(builtInPreset(Scene{}.shading.shading == Shading::Gouraud));
    m_document.set(Scene{});
    m_status->showMessage(hadEdits ? tr("Everything reset; Ctrl+Z in the editor brings your "
                                        "shader text back")
                                   : tr("Everything reset"));
}

void MainWindow::syncShadingWithProgram()
{
    // A program whose text fixes its model (an edited built-in keeps the shading it was
    // written for, the slides' shaders theirs and N.H): the scene takes that model, so the
    // panel, the probe's reference and the status line describe what draws, and the
    // shading choice is greyed with the reason.
    const ShaderDocument::FixedModel fixed = m_shaders.fixedModel();
    // The reference computes V from the projection; the slides' shaders take (0,0,1).
    const bool otherView =
        fixed.parallelView && m_document.scene().shading.projection == Projection::Perspective;
    m_probe->setReferenceNote(
        otherView ? tr("The program on screen computes V = (0,0,1), the parallel view vector, "
                       "under the perspective projection; the reference uses V = -P, so the two "
                       "differ away from the middle of the view. The orthographic projection "
                       "(key P) makes them agree.")
                  : QString());
    if (fixed.gouraud || fixed.blinn)
        m_document.edit([&](Scene &s) {
            if (fixed.gouraud)
                s.shading.shading = *fixed.gouraud ? Shading::Gouraud : Shading::Phong;
            if (fixed.blinn)
                s.shading.specular = *fixed.blinn ? SpecularModel::Blinn : SpecularModel::Phong;
        });
    if (!fixed.gouraud) {
        m_shading->setShadingFixed(false, {});
        return;
    }
    const Shading drawn = *fixed.gouraud ? Shading::Gouraud : Shading::Phong;
    m_shading->setShadingFixed(
        true, tr("The program in the editor (%1) shades %2 (%3) whatever this says. Load a "
                 "preset or Reset Everything to switch shading.")
                  .arg(m_editor->programName(), toName(drawn),
                       drawn == Shading::Gouraud ? tr("per vertex") : tr("per fragment")));
}

void MainWindow::showProgramUsage(const ProgramBuild &build)
{
    if (!build.ok())
        return; // the last good program, and what it reads, stay
    std::set<Semantic> read;
    for (const ActiveUniform &u : build.uniforms)
        if (u.semantic)
            read.insert(*u.semantic);
    for (ScenePanel *panel :
         {static_cast<ScenePanel *>(m_light), static_cast<ScenePanel *>(m_material),
          static_cast<ScenePanel *>(m_shading)})
        panel->showUsage(read);
    m_uniforms->setUniforms(build.uniforms);
    m_programReadsLight = build.readsLightPosition();
    updateStatus();
}

void MainWindow::updateStatus()
{
    const Scene &s = m_document.scene();
    // One light: what it is and its frame; several: how many are on.
    int on = 0;
    for (const Light &l : s.lights)
        on += l.enabled ? 1 : 0;
    const Light &first = s.lights[0];
    QString light = tr("%1 lights on").arg(on);
    if (!m_programReadsLight)
        light = tr("the program's own light (marker hidden)");
    else if (on == 1 && first.enabled)
        light = (first.position.w == 0.0f ? tr("directional light") : tr("point light")) +
                tr(" in the %1 frame").arg(toName(first.frame));
    m_viewport->setProgramName(m_editor->programName()); // side A of a compare view
    QString program = tr("Program: %1").arg(m_editor->programName());
    if (m_shaders.showsBuiltIn()) // the Shading panel's specular choice applies
        program += s.shading.specular == SpecularModel::Blinn
                       ? tr(", Blinn-Phong specular (N\u00b7H)")
                       : tr(", Phong specular (R\u00b7V)");
    m_status->setProgram(
        QString("%1  |  %2  |  %3 projection").arg(program, light, toName(s.shading.projection)));
}

void MainWindow::updateTitle()
{
    QString name = m_sceneActions->documentName();
    bool modified = m_sceneActions->isModified();
    if (name.isEmpty() && !m_shaders.filePath(ShaderStage::Vertex).isEmpty()) {
        name = QFileInfo(m_shaders.filePath(ShaderStage::Vertex)).completeBaseName();
        modified = m_shaders.isModified();
    }
    if (name.isEmpty())
        name = tr("untitled");
    setWindowTitle(tr("%1[*] - lightbench").arg(name));
    setWindowModified(modified);
}

void MainWindow::saveSettings()
{
    m_settings.setValue(kSceneKey, QJsonDocument(m_document.scene().toJson()).toJson());
    // Presentation mode is for the session: the window as it was before it is what is kept.
    m_settings.setValue(kGeometryKey, m_presentation ? m_normalGeometry : saveGeometry());
    m_settings.setValue(kStateKey, m_presentation ? m_normalState : saveState(kStateVersion));
    m_settings.setValue(kScreenKey, m_available.size());
    m_settings.setValue(kLayoutKey, int(m_presentation ? m_normalLayout : m_layout));
    m_editor->saveState(m_settings);
    m_settings.sync();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    event->accept();
}

} // namespace lb
