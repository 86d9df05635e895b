#include "main_window.h"

#include "editor_panel.h"
#include "light_panel.h"
#include "material_panel.h"
#include "mesh_actions.h"
#include "object_loader.h"
#include "object_panel.h"
#include "presets.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "shading_panel.h"
#include "uniform_panel.h"
#include "viewport.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QJsonDocument>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>

namespace lb {

namespace {
constexpr int kStateVersion = 3; // 2: the editor dock, 3: the probe dock
const char *kSceneKey = "scene";
const char *kGeometryKey = "window/geometry";
const char *kStateKey = "window/state";

// A dock whose panel scrolls when the screen is too short for it.
QDockWidget *addDock(QMainWindow *window, const QString &title, const QString &objectName,
                     QWidget *panel, Qt::DockWidgetArea area)
{
    auto *scroll = new QScrollArea;
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *dock = new QDockWidget(title, window);
    dock->setObjectName(objectName); // saveState() needs it
    dock->setWidget(scroll);
    window->addDockWidget(area, dock);
    return dock;
}
} // namespace

MainWindow::MainWindow(QSettings &settings, QWidget *parent)
    : QMainWindow(parent), m_settings(settings)
{
    setWindowTitle(tr("lightbench"));
    const QByteArray savedScene = m_settings.value(kSceneKey).toByteArray();
    if (!savedScene.isEmpty())
        m_document.set(Scene::fromJson(QJsonDocument::fromJson(savedScene).object()));

    m_viewport = new Viewport(&m_document, this);
    setCentralWidget(m_viewport);
    m_loader = new ObjectLoader(&m_document, this);
    connect(m_loader, &ObjectLoader::meshReady, m_viewport, &Viewport::setObject);
    m_viewport->setObject(m_loader->mesh(), m_loader->texture());
    m_light = new LightPanel(&m_document);
    m_material = new MaterialPanel(&m_document);
    m_shading = new ShadingPanel(&m_document);
    m_object = new ObjectPanel(&m_document);
    addDock(this, tr("Light"), "lightDock", m_light, Qt::LeftDockWidgetArea);
    addDock(this, tr("Material"), "materialDock", m_material, Qt::LeftDockWidgetArea);
    QDockWidget *shadingDock =
        addDock(this, tr("Shading"), "shadingDock", m_shading, Qt::LeftDockWidgetArea);
    QDockWidget *objectDock =
        addDock(this, tr("Object"), "objectDock", m_object, Qt::LeftDockWidgetArea);
    tabifyDockWidget(shadingDock, objectDock);
    m_uniforms = new UniformPanel(&m_document);
    QDockWidget *uniformDock =
        addDock(this, tr("Shader uniforms"), "uniformDock", m_uniforms, Qt::LeftDockWidgetArea);
    tabifyDockWidget(objectDock, uniformDock);
    shadingDock->raise();
    m_probe = new ProbePanel(&m_document, m_viewport);
    QDockWidget *probeDock =
        addDock(this, tr("Probe"), "probeDock", m_probe, Qt::LeftDockWidgetArea);
    tabifyDockWidget(uniformDock, probeDock);
    shadingDock->raise();
    connect(m_viewport, &Viewport::probeRequested, this, [this, probeDock](QPoint pixel) {
        m_probe->probeAt(pixel);
        probeDock->show();
        probeDock->raise();
    });

    m_editor = new EditorPanel(&m_shaders);
    auto *editorDock = new QDockWidget(tr("Shader editor"), this);
    editorDock->setObjectName("editorDock");
    editorDock->setWidget(m_editor);
    addDockWidget(Qt::RightDockWidgetArea, editorDock);
    resizeDocks({editorDock}, {520}, Qt::Horizontal);
    connect(m_editor, &EditorPanel::compileRequested, m_viewport, &Viewport::compileProgram);
    connect(m_viewport, &Viewport::programBuilt, m_editor, &EditorPanel::showBuild);
    connect(m_viewport, &Viewport::programBuilt, this, &MainWindow::showProgramUsage);
    if (!m_editor->restoreState(m_settings))
        m_editor->loadPreset(builtInPreset(m_document.scene().shading.shading == Shading::Gouraud));
    connect(&m_shaders, &ShaderDocument::changed, this, [this] {
        updateStatus();
        if (!m_saveTimer.isActive())
            m_saveTimer.start();
    });

    m_meshActions = new MeshActions(this, &m_document, m_loader, m_settings);
    connect(m_meshActions, &MeshActions::shaderFilesDropped, this,
            [this](const QStringList &paths) {
                if (const QString error = m_shaders.openFiles(paths); !error.isEmpty())
                    QMessageBox::warning(this, tr("Shader files"), error);
            });
    m_sceneActions = new SceneActions(this, &m_document, &m_shaders, m_viewport, m_settings);
    connect(m_meshActions, &MeshActions::sceneFileDropped, m_sceneActions, &SceneActions::open);
    connect(m_object, &ObjectPanel::openMeshRequested, m_meshActions, &MeshActions::showOpenDialog);
    connect(m_object, &ObjectPanel::adoptFileMaterialRequested, m_loader,
            &ObjectLoader::setAdoptFileMaterial);
    m_glLabel = new QLabel(this);
    statusBar()->addPermanentWidget(m_glLabel);
    connect(m_viewport, &Viewport::glInfo, m_glLabel, &QLabel::setText);
    buildMenus();

    resize(1366, 768);
    restoreGeometry(m_settings.value(kGeometryKey).toByteArray());
    restoreState(m_settings.value(kStateKey).toByteArray(), kStateVersion);

    m_saveTimer.setSingleShot(true);
    m_saveTimer.setInterval(500);
    connect(&m_saveTimer, &QTimer::timeout, this, &MainWindow::saveSettings);
    connect(&m_document, &SceneDocument::changed, this, [this](SceneParts parts) {
        updateStatus();
        if (parts & ScenePart::Shading)
            m_shaders.followShading(m_document.scene().shading.shading == Shading::Gouraud);
        // Not restarted on every change: auto-rotate edits the scene 60 times a second,
        // and a timer restarted that often would never fire.
        if (!m_saveTimer.isActive())
            m_saveTimer.start();
    });
    updateStatus();
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
    addItem(file, tr("&Open Shaders..."), QKeySequence::Open, [this, filter, report] {
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
    addItem(file, tr("&Save Shaders"), QKeySequence::Save, [this, saveAs, report] {
        if (m_shaders.filePath(ShaderStage::Vertex).isEmpty())
            saveAs();
        else
            report(m_shaders.save());
    });
    addItem(file, tr("Save Shaders &As..."), QKeySequence(tr("Ctrl+Shift+S")), saveAs);
    file->addSeparator();
    QMenu *edit = new QMenu(tr("&Edit"), this); // filled below, shown after File
    QMenu *view = new QMenu(tr("&View"), this);
    m_meshActions->addToMenus(file, edit, view);
    file->addSeparator();
    addItem(file, tr("Reset &Everything"), QKeySequence(tr("Ctrl+Shift+R")),
            [this] { m_document.set(Scene{}); });
    file->addSeparator();
    addItem(file, tr("&Quit"), QKeySequence::Quit, [this] { close(); });
    menuBar()->addMenu(edit);

    QMenu *shading = menuBar()->addMenu(tr("&Shading"));
    addItem(shading, tr("Toggle &Gouraud / Phong"), QKeySequence(tr("G")), [this] {
        m_document.edit([](Scene &s) {
            s.shading.shading =
                s.shading.shading == Shading::Phong ? Shading::Gouraud : Shading::Phong;
        });
    });
    addItem(shading, tr("Toggle Phong / &Blinn-Phong specular"), QKeySequence(tr("B")), [this] {
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
    view->addSeparator();
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        view->addAction(dock->toggleViewAction());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    addItem(help, tr("&Controls"), QKeySequence::HelpContents, [this] {
        QMessageBox::information(
            this, tr("Controls"),
            tr("Left drag: orbit the camera\nRight or middle drag: pan\nWheel: zoom\n"
               "R: reset the camera\nSpace: auto-rotate the object\n"
               "N: show normals as lines\nCtrl+M: open a mesh (or drop one on the window)\n"
               "Ctrl+Shift+O / Ctrl+Alt+S: open / save a scene\n"
               "Ctrl+E: export the view as an image\nCtrl+Shift+C: copy the view\n"
               "G: Gouraud / Phong shading\nB: Phong / Blinn-Phong specular\n"
               "P: perspective / orthographic\nL: lighting on / off\n"
               "Ctrl+click or Shift+click: probe the surface (drag to move it), Esc: clear\n"
               "C: compare off / side by side / wipe / difference (drag the wipe's line)\n"
               "Ctrl+Shift+R: reset everything"));
    });
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
    if (on == 1 && first.enabled)
        light = (first.position.w == 0.0f ? tr("directional light") : tr("point light")) +
                tr(" in the %1 frame").arg(toName(first.frame));
    QString program = tr("Program: %1").arg(m_editor->programName());
    if (m_shaders.showsBuiltIn()) // the Shading panel's choices apply
        program += s.shading.specular == SpecularModel::Blinn
                       ? tr(", Blinn-Phong specular (N\u00b7H)")
                       : tr(", Phong specular (R\u00b7V)");
    statusBar()->showMessage(
        QString("%1  |  %2  |  %3 projection").arg(program, light, toName(s.shading.projection)));
}

void MainWindow::saveSettings()
{
    m_settings.setValue(kSceneKey, QJsonDocument(m_document.scene().toJson()).toJson());
    m_settings.setValue(kGeometryKey, saveGeometry());
    m_settings.setValue(kStateKey, saveState(kStateVersion));
    m_editor->saveState(m_settings);
    m_settings.sync();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    event->accept();
}

} // namespace lb
