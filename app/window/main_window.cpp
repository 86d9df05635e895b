#include "main_window.h"

#include "binding_panel.h"
#include "editor_panel.h"
#include "exercise_panel.h"
#include "file_arguments.h"
#include "lesson_actions.h"
#include "lesson_bar.h"
#include "light_panel.h"
#include "main_window_settings.h"
#include "material_panel.h"
#include "mesh_actions.h"
#include "message_text.h"
#include "object_loader.h"
#include "object_panel.h"
#include "plots_panel.h"
#include "presets.h"
#include "probe_panel.h"
#include "scene_actions.h"
#include "scene_file.h"
#include "scene_phrases.h"
#include "settings_autosave.h"
#include "shading_panel.h"
#include "status_line.h"
#include "texture_controls.h"
#include "uniform_panel.h"
#include "viewport.h"

#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QVBoxLayout>

#include <algorithm>

namespace lb {

using namespace window_settings;

MainWindow::MainWindow(QSettings &settings, QWidget *parent)
    : QMainWindow(parent), m_settings(settings)
{
    limitScenes(); // before the first scene
    const QByteArray savedScene = m_settings.value(kSceneKey).toByteArray();
    if (!savedScene.isEmpty())
        m_restoreLimited =
            m_document.set(Scene::fromJson(QJsonDocument::fromJson(savedScene).object()));
    m_scale = clampUiScale(m_settings.value(kScaleKey, 1.0).toDouble());
    m_presentationScale = clampUiScale(m_settings.value(kPresentationScaleKey, 1.75).toDouble());
    applyUiScale(m_scale); // before the widgets, which size themselves by the font

    m_viewport = new Viewport(&m_document, this);
    // The lesson bar sits under the view, in the central area: presentation mode keeps it.
    auto *central = new QWidget(this);
    central->setObjectName("viewArea");
    auto *centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->setSpacing(0);
    centralLayout->addWidget(m_viewport, 1);
    auto *lessonBar = new LessonBar(central);
    centralLayout->addWidget(lessonBar);
    setCentralWidget(central);
    m_loader = new ObjectLoader(&m_document, this);
    connect(m_loader, &ObjectLoader::meshReady, m_viewport, &Viewport::setObject);
    connect(m_loader, &ObjectLoader::objectCountChanged, m_viewport, &Viewport::setObjectCount);
    m_viewport->setObjectCount(m_loader->objectCount());
    for (int i = 0; i < m_loader->objectCount(); ++i)
        m_viewport->setObject(i, m_loader->mesh(i), m_loader->texture(i));
    m_light = new LightPanel(&m_document);
    m_material = new MaterialPanel(&m_document);
    m_shading = new ShadingPanel(&m_document);
    m_object = new ObjectPanel(&m_document);
    m_uniforms = new UniformPanel(&m_document);
    m_bindings = new BindingPanel(&m_document);
    m_probe = new ProbePanel(&m_document, m_viewport);
    addPanelDock(tr("Light"), "lightDock", m_light);
    addPanelDock(tr("Material"), "materialDock", m_material);
    addPanelDock(tr("Shading"), "shadingDock", m_shading);
    addPanelDock(tr("Object"), "objectDock", m_object);
    addPanelDock(tr("Uniforms"), "uniformDock", m_uniforms);
    addPanelDock(tr("Bindings"), "bindingDock", m_bindings);
    QDockWidget *probeDock = addPanelDock(tr("Probe"), "probeDock", m_probe);
    m_plots = new PlotsPanel(&m_document, m_probe);
    m_plots->restoreState(m_settings);
    addPanelDock(tr("Plots"), "plotsDock", m_plots);
    m_exercisePanel = new ExercisePanel;
    m_exerciseDock = addPanelDock(tr("Exercise"), "exerciseDock", m_exercisePanel);
    // A click on an object selects it for the Object and Material panels.
    connect(m_viewport, &Viewport::clicked, this, &MainWindow::selectObjectAt);
    connect(m_viewport, &Viewport::probeRequested, this, [this, probeDock](QPoint pixel) {
        m_probe->probeAt(pixel);
        bringForward(probeDock); // in presentation mode the numbers wait behind F6
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
    m_autosave = new SettingsAutosave(
        m_settings, m_status, [this] { writeSettings(); }, this);
    statusBar()->addPermanentWidget(m_status, 1);
    connect(m_viewport, &Viewport::glInfo, this, [this](const QString &info) {
        m_glInfo = info;
        m_status->driverLabel()->setText(info);
    });

    if (!m_editor->restoreState(m_settings))
        m_editor->loadPreset(builtInPreset(perVertex(m_document.scene().shading.shading)));
    m_editor->setUiScale(m_scale);
    connect(&m_shaders, &ShaderDocument::changed, this, [this] {
        syncShadingWithProgram();
        updateStatus();
        updateTitle();
        m_autosave->schedule();
    });

    m_meshActions = new MeshActions(this, &m_document, m_loader, m_settings, m_status);
    m_meshActions->setViewSize([this] { return m_viewport->size(); });
    connect(m_meshActions, &MeshActions::imageDropped, this,
            [this](const QString &path, QPoint globalPos) {
                const QPoint local = m_viewport->mapFromGlobal(globalPos);
                if (m_viewport->rect().contains(local))
                    selectObjectAt((QPointF(local) * m_viewport->devicePixelRatio()).toPoint());
                m_meshActions->openImage(path);
            });
    connect(m_meshActions, &MeshActions::shaderFilesDropped, this,
            [this](const QStringList &paths) {
                if (const QString error = m_shaders.openFiles(paths); !error.isEmpty())
                    QMessageBox::warning(this, tr("Shader files"), error);
            });
    m_viewport->setFrameBudget(m_meshActions->frameBudgetSeconds() * 1000.0);
    connect(m_meshActions, &MeshActions::frameBudgetChanged, this,
            [this](double seconds) { m_viewport->setFrameBudget(seconds * 1000.0); });
    m_sceneActions = new SceneActions(this, &m_document, &m_shaders, m_viewport, m_settings);
    setUpExercise(); // the Exercise panel, Check my work and side B
    // Opening a scene asks first when work would be set aside. A dropped one is opened once
    // the drop is over: the drag's source is not kept waiting on the question.
    m_sceneActions->setMaySetAside(
        [this](const QString &target) { return maySetAside(SetAsideFor::OpeningScene, target); });
    m_lessons = new LessonActions(this, lessonBar, m_settings);
    connect(lessonBar, &LessonBar::visibilityChanged, this, &MainWindow::placeStatusMessage);
    connect(m_status, &StatusLine::messageChanged, this, &MainWindow::placeStatusMessage);
    m_lessons->setMaySetAside([this](SetAsideFor occasion, const QString &target) {
        return maySetAside(occasion, target);
    });
    connect(m_lessons, &LessonActions::changed, this, &MainWindow::updateTitle);
    connect(
        m_meshActions, &MeshActions::sceneFileDropped, m_sceneActions,
        [this](const QString &path) {
            if (documentKind(path) == DocumentKind::Lesson)
                m_lessons->openAsking(path);
            else
                m_sceneActions->openAsking(path);
        },
        Qt::QueuedConnection);
    connect(m_sceneActions, &SceneActions::documentChanged, this, &MainWindow::updateTitle);
    connect(m_sceneActions, &SceneActions::sceneOpened, m_probe, &ProbePanel::clear);
    connect(m_object, &ObjectPanel::openMeshRequested, m_meshActions, &MeshActions::showOpenDialog);
    connect(m_object, &ObjectPanel::openImageRequested, m_meshActions,
            &MeshActions::showImageDialog);
    connect(m_object, &ObjectPanel::adoptFileMaterialRequested, m_loader,
            &ObjectLoader::setAdoptFileMaterial);
    // Files the scene names that could not be used are still named: the panel says why.
    m_object->setProblemLookups([this] { return m_loader->meshProblem(); },
                                [this] { return m_loader->textureProblem(); });
    connect(m_loader, &ObjectLoader::loadFinished, m_object, &ObjectPanel::refreshProblems);
    connect(m_loader, &ObjectLoader::textureFinished, m_object, &ObjectPanel::refreshProblems);
    setUpSceneBudget(); // the Object panel's bound and the status line's messages
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
        applyTabPositions(); // first: a tab bar down the edge takes width from the docks
        if (restoreState(m_settings.value(kStateKey).toByteArray(), kStateVersion))
            m_widthsPending = false; // the user's own dock sizes
    }

    connect(&m_document, &SceneDocument::changed, this, [this](SceneParts parts) {
        updateStatus();
        updateTitle();
        if (parts & ScenePart::Shading) {
            m_shaders.followShading(perVertex(m_document.scene().shading.shading));
            syncShadingWithProgram(); // a reset or an option cannot unfix a fixed model
        }
        m_autosave->schedule();
    });
    syncShadingWithProgram();
    updateStatus();
    updateTitle();
    m_exerciseDock->setVisible(m_sceneActions->exercise().has_value()); // a saved state's aside
    m_lessons->restoreSession(); // after the session's scene and program: they are its step's
    if (m_editor->restoredUnsavedEdits())
        m_status->showMessage(tr("Unsaved shader edits from the last session are back"), 20000);
}

void MainWindow::resetEverything()
{
    if (!maySetAside(SetAsideFor::ResettingEverything))
        return;
    m_sceneActions->forgetFile(); // Ctrl+S must not write the defaults over the file
    // The editor first (undoable there): while an edited program still drew, the scene's
    // shading would be held to that program's.
    const bool hadEdits = !m_shaders.showsBuiltIn();
    m_shaders.loadPreset(builtInPreset(perVertex(Scene{}.shading.shading)));
    m_probe->clear(); // the camera and the object are new: the arrows' view is gone
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
    if (fixed.gouraud || fixed.specular)
        m_document.edit([&](Scene &s) {
            if (fixed.gouraud)
                s.shading.shading = *fixed.gouraud ? Shading::Gouraud : Shading::Phong;
            if (fixed.specular)
                s.shading.specular = *fixed.specular;
        });
    if (!fixed.gouraud) {
        // Only the built-in program follows the choice (it is two programs, switched); any
        // other shades as it is written, and the choice would change nothing on screen.
        m_shading->setShadingFixed(
            !m_shaders.showsBuiltIn(),
            tr("%1 shades as it is written: Gouraud/Phong does not change it. A preset or "
               "Reset Everything brings the built-in program, which follows this choice.")
                .arg(m_editor->programName()));
        return;
    }
    // A whole sentence per model: the model's name and its gloss go together.
    m_shading->setShadingFixed(
        true, (*fixed.gouraud ? tr("The program in the editor (%1) shades Gouraud (per vertex) "
                                   "whatever this says. Load a preset or Reset Everything to "
                                   "switch shading.")
                              : tr("The program in the editor (%1) shades Phong (per fragment) "
                                   "whatever this says. Load a preset or Reset Everything to "
                                   "switch shading."))
                  .arg(m_editor->programName()));
}

void MainWindow::showProgramUsage(const ProgramBuild &build)
{
    if (!build.ok())
        return; // the last good program, and what it reads, stay
    std::set<Semantic> read;
    for (const ActiveUniform &u : build.uniforms)
        if (u.semantic)
            for (Semantic s : controlledBy(*u.semantic))
                read.insert(s);
    for (ScenePanel *panel :
         {static_cast<ScenePanel *>(m_light), static_cast<ScenePanel *>(m_material),
          static_cast<ScenePanel *>(m_shading)})
        panel->showUsage(read);
    m_uniforms->setUniforms(build.uniforms);
    m_bindings->setProgram(build, !m_shaders.showsBuiltIn());
    m_programReadsLight = build.readsLightPosition();
    updateStatus();
}

void MainWindow::updateStatus()
{
    m_viewport->setProgramName(m_editor->programName()); // side A of a compare view
    m_status->setProgram(statusDescription(m_document.scene(), m_editor->programName(),
                                           m_shaders.showsBuiltIn(), m_programReadsLight));
}

void MainWindow::updateTitle()
{
    QString name = m_sceneActions->documentName();
    if (m_lessons && m_lessons->isOpen()) // the lesson is the document
        name =
            tr("%1, step %2").arg(m_lessons->name(), QString::number(m_lessons->currentStep() + 1));
    if (name.isEmpty() && !m_shaders.filePath(ShaderStage::Vertex).isEmpty())
        name = QFileInfo(m_shaders.filePath(ShaderStage::Vertex)).completeBaseName();
    if (name.isEmpty())
        name = tr("untitled");
    setWindowTitle(tr("%1[*] - lightbench").arg(escapedName(name))); // a file name's controls
    setWindowModified(unsavedWork().any()); // the * is what quit and close ask about
}

void MainWindow::saveSettings()
{
    m_autosave->saveNow();
}

void MainWindow::writeSettings()
{
    m_settings.setValue(kSceneKey, QJsonDocument(ownScene().toJson()).toJson());
    // Presentation mode is for the session: the window as it was before it is what is kept.
    m_settings.setValue(kGeometryKey, m_presentation ? m_normalGeometry : saveGeometry());
    m_settings.setValue(kStateKey, m_presentation ? m_normalState : saveState(kStateVersion));
    m_settings.setValue(kScreenKey, m_available.size());
    m_settings.setValue(kLayoutKey, int(m_presentation ? m_normalLayout : m_layout));
    m_editor->saveState(m_settings);
    m_plots->saveState(m_settings);
    if (m_sessionKeepsOnlySaved)
        writeSavedWork();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    const SetAside setAside = askToSetAside(SetAsideFor::Closing);
    if (setAside == SetAside::Cancelled) {
        event->ignore(); // the window, and the edit, stay
        return;
    }
    m_sessionKeepsOnlySaved = setAside == SetAside::Discarded;
    saveSettings();
    m_sessionKeepsOnlySaved = false;
    if (setAside == SetAside::Discarded) {
        event->accept(); // nothing is kept that the user threw away
        return;
    }
    if (m_autosave->isFailing())
        keepUnsavedSession();
    else if (setAside == SetAside::NotAsked) // a run without a user: no question, no loss
        qInfo("lightbench: closed without asking; the unsaved changes are kept in the session "
              "(%s) and come back at the next start, not in their files",
              qPrintable(m_autosave->fileName()));
    event->accept();
}

void MainWindow::keepUnsavedSession()
{
    // No dialog: a window closed by a script (--screenshot) must not wait for a click.
    const QString path =
        QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation))
            .filePath(QString("lightbench-unsaved-%1.json")
                          .arg(QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss")));
    const QString error =
        writeSceneFile(path, SceneFile{ownScene(), m_shaders.program(), std::nullopt});
    if (error.isEmpty())
        qWarning("lightbench: the session could not be saved in %s; it is in %s (File > Open)",
                 qPrintable(m_autosave->fileName()), qPrintable(path));
    else
        qWarning("lightbench: the session could not be saved in %s, nor in %s",
                 qPrintable(m_autosave->fileName()), qPrintable(error));
}

void MainWindow::selectObjectAt(QPoint framePixel)
{
    const QSize frame = m_viewport->size() * m_viewport->devicePixelRatio();
    const ProbeResult hit = probeFramePixel(
        m_document.scene(), m_viewport->renderer().probedObjects(), frame, framePixel);
    if (hit.hit)
        m_document.edit([&](Scene &s) { s.selected = hit.object; });
}

QStringList MainWindow::unsettledParts() const
{
    QStringList parts;
    if (m_loader->isLoading())
        parts << QStringLiteral("loading a file");
    if (m_loader->isBuilding())
        parts << QStringLiteral("building an object");
    if (m_loader->isDecodingTexture())
        parts << QStringLiteral("decoding a texture");
    if (m_editor->isCompilePending())
        parts << QStringLiteral("waiting for the live compile's pause");
    if (m_viewport->isTrying())
        parts << QStringLiteral("trying a program");
    return parts;
}

bool MainWindow::isSettled() const
{
    return unsettledParts().isEmpty();
}

} // namespace lb
