#pragma once
// The workbench window: the viewport in the centre, the panels docked on the left, the shader
// editor on the right. It takes the screen's available area (never more) and arranges the
// docks for that width (window_layout.h); presentation mode (F11) is full screen with its own
// UI scale. Scene, window layout, docks, scales and zoom are kept in QSettings and come back
// at the next start. A lesson's bar sits under the viewport (lesson_actions.h).

#include "program_build.h"
#include "scene_budget.h"
#include "scene_document.h"
#include "shader_document.h"
#include "unsaved_work.h"
#include "window_layout.h"

#include <QMainWindow>
#include <QPointer>
#include <QStringList>

#include <optional>
#include <vector>

class QActionGroup;
class QDockWidget;
class QSettings;

namespace lb {

class EditorPanel;
class ExercisePanel;
class LessonActions;
class LightPanel;
class MaterialPanel;
class MeshActions;
class ObjectLoader;
class ObjectPanel;
class PlotsPanel;
class ProbePanel;
class SceneActions;
class ScreenBlank;
class SettingsAutosave;
class ShadingPanel;
class StatusLine;
class UniformPanel;
class BindingPanel;
class Viewport;
class WorkCheck;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // `settings` outlives the window; the scene starts from what it holds.
    MainWindow(QSettings &settings, QWidget *parent = nullptr);

    SceneDocument &document() { return m_document; }
    ShaderDocument &shaderDocument() { return m_shaders; }
    Viewport *viewport() const { return m_viewport; }
    LightPanel *lightPanel() const { return m_light; }
    MaterialPanel *materialPanel() const { return m_material; }
    ShadingPanel *shadingPanel() const { return m_shading; }
    ObjectPanel *objectPanel() const { return m_object; }
    EditorPanel *editorPanel() const { return m_editor; }
    UniformPanel *uniformPanel() const { return m_uniforms; }
    BindingPanel *bindingPanel() const { return m_bindings; }
    ObjectLoader *objectLoader() const { return m_loader; }
    // Nothing on its way to the picture: every object and texture is in, no typed text waits
    // for the live compile and no program is being tried (what is drawn now stays drawn;
    // --screenshot waits for it).
    bool isSettled() const;
    // What keeps it from being settled, in words for a message ("loading a file", "trying a
    // program"); empty when settled.
    QStringList unsettledParts() const;
    MeshActions *meshActions() const { return m_meshActions; }
    SceneActions *sceneActions() const { return m_sceneActions; }
    LessonActions *lessonActions() const { return m_lessons; } // the lesson bar's too
    ProbePanel *probePanel() const { return m_probe; }
    PlotsPanel *plotsPanel() const { return m_plots; }
    StatusLine *statusLine() const { return m_status; }
    ExercisePanel *exercisePanel() const { return m_exercisePanel; }
    QDockWidget *exerciseDock() const { return m_exerciseDock; }
    QAction *checkAction() const { return m_checkAction; } // File > Check My Work (F9)
    WorkCheck *workCheck() const { return m_workCheck; }
    // Side B of the compare views draws the shader pair at `path` (NAME.vert/NAME.frag, either
    // file, or a scene file's program); empty: what it drew before (the exercise's reference
    // or the built-in program). Returns an empty string or the message shown.
    QString setSideBFiles(const QString &path);
    SettingsAutosave *autosave() const { return m_autosave; }
    // The docks of the panels (Light, Material, Shading, Object, Uniforms, Probe, Plots, Exercise;
    // the Exercise dock is hidden while no exercise is open) and the editor's.
    const std::vector<QDockWidget *> &panelDocks() const { return m_panelDocks; }
    QDockWidget *editorDock() const { return m_editorDock; }

    // Takes `available` (a screen's available area): the window's geometry within it and the
    // docks arranged for its width. The constructor calls it with the window's screen.
    void fitToScreen(const QRect &available);
    void arrangeDocks(DockLayout layout);
    DockLayout dockLayout() const { return m_layout; }

    // Presentation mode: full screen, the presentation UI scale, the view and the editor
    // large; off brings back the window as it was.
    void setPresentation(bool on);
    bool isPresentation() const { return m_presentation; }
    // In presentation mode the panels and the editor are hidden behind F6 (View > Show Panels
    // in Presentation Mode), so the view keeps the screen; B or . blanks it (the clicker's
    // keys, main_window_presentation.cpp).
    void setPresentationPanels(bool shown);
    bool presentationPanelsShown() const;
    // Whether presentation mode keeps the panels behind F6 now: the view has the screen.
    bool panelsWaitBehindF6() const { return m_presentation && !presentationPanelsShown(); }
    // Shows `dock` in front (a lesson step's panel, the Exercise panel as an exercise opens);
    // while the panels wait behind F6 it stays there, and is the one in front when F6 shows
    // them: a step never takes the view's screen on its own (issue 49).
    void bringForward(QDockWidget *dock);
    ScreenBlank *screenBlank() const { return m_blank; }
    // The UI scale of the current mode (1.0 to 2.5), kept per mode in the settings.
    void setUiScale(double scale);
    double uiScale() const;

    // Saves the session (scene, layout, editor) now; a change saves it shortly after anyway.
    void saveSettings();

    // Work not in its files (the title's *): the scene, and the shader files with edits.
    UnsavedWork unsavedWork() const;
    // Who is asked before quit, close, another scene or Reset Everything set that work aside.
    // None, as constructed: nothing is asked and nothing waits (a run without a user: tests,
    // --screenshot, --bench-edits); main() gives a user's window askAboutUnsavedWork.
    void setUnsavedWorkAsker(UnsavedWorkAsker asker) { m_asker = std::move(asker); }
    // The one place that decides whether the unsaved work may be set aside for `occasion`
    // (`target`: the scene about to be opened): true when nothing is unsaved, when there is
    // no one to ask, after Discard, or after Save wrote everything; false after Cancel, or a
    // save that failed (its message is shown) or whose Save As dialog was cancelled.
    bool maySetAside(SetAsideFor occasion, const QString &target = {});
    // File > Save Shaders (As): true once written; false when cancelled or refused (said).
    bool saveShaders();
    bool saveShadersAs();

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    // A click in the view (or an image dropped there) selects the object under it, if any.
    void selectObjectAt(QPoint framePixel);
    QDockWidget *addPanelDock(const QString &title, const QString &objectName, QWidget *panel);
    void writeSettings(); // puts the session's values into the settings, for the autosave
    // What maySetAside() came to (main_window_unsaved.cpp).
    enum class SetAside { NothingUnsaved, NotAsked, Saved, Discarded, Cancelled };
    SetAside askToSetAside(SetAsideFor occasion, const QString &target = {});
    bool saveUnsavedWork(const UnsavedWork &work);
    // Discard at close: the session's scene and program become what the files hold.
    void writeSavedWork();
    bool untitledProgramInFiles() const; // an untitled scene's program is a shader pair's
    // Closing while the autosave fails: the scene and program go to a scene file in the
    // temporary folder, named on stderr, instead of being lost.
    void keepUnsavedSession();
    void buildMenus();
    void addViewMenu(QMenu *view);
    // The clicker's keys and presentation mode's own actions (main_window_presentation.cpp).
    void addPresentationActions(QMenu *view);
    void blankPressed();                 // B or .: the screen black in presentation mode
    void escapePressed();                // Esc: out of presentation mode, else the probe cleared
    void presentationChanged();          // after setPresentation(): panels, status line, blank
    bool presentationEditorFits() const; // the editor fits beside a view of 60% of the width
    void styleDockTabs(); // the docks' tab bars: names whole, their font in presentation mode
    // The docks' tab names in presentation mode at `share` of the 100% font (styleDockTabs()
    // picks it: 140%, less where the names would not fit the column).
    QFont presentationTabFont(double share) const;
    int presentationTabsWidth() const; // the column of tabs down the edge in presentation mode
    void updateStatus();
    void updateTitle();
    void showProgramUsage(const ProgramBuild &build);
    void syncShadingWithProgram();
    void resetEverything();
    void applyScale();
    // Whether the panels' forms stack their rows and wrap their switches (narrow_forms.h).
    void stackPanelForms(bool on);
    void placeStatusMessage(); // the status line, or the lesson bar in presentation mode
    void applyDockWidths();
    void scaleDockTitles();   // their titles in the panels' font (at every UI scale)
    void keepTheViewsShare(); // applyDockWidths() where a restored state leaves the view < 45%
    int panelsNeed() const;   // the width the widest panel needs, without scrolling sideways
    void applyTabPositions();
    bool presentationIsShort() const; // a screen under 900 lines: panels beside the editor
    void keepInsideScreen();
    // The Exercise panel, Check my work and side B (main_window_exercise.cpp).
    void setUpExercise();
    void exerciseChanged();
    void applySideB();
    void holdSideBToReference(); // a built-in reference's choices stay side B's
    void checkWork();
    void showCase(int index);
    void showOwnScene();
    void markCheckOutOfDate(); // the Exercise panel's outcome, when the program has changed
    // The student's scene: the one before the first case was shown while one is, else the
    // document's. What saves write.
    Scene ownScene() const;
    void chooseSideBFiles();
    // The scene budget (main_window_budget.cpp): every scene the document takes is held to
    // it (limitScenes(), first), the Object panel's tessellation box too, and what was
    // lowered is said on the status line.
    void limitScenes();
    void setUpSceneBudget();
    MeshFileSizes loadedFileSizes() const;
    QString m_restoreLimited; // what the budget lowered in the restored session's scene

    QSettings &m_settings;
    SceneDocument m_document;
    ShaderDocument m_shaders; // the program in the editor
    Viewport *m_viewport;
    LightPanel *m_light;
    MaterialPanel *m_material;
    ShadingPanel *m_shading;
    ObjectPanel *m_object;
    EditorPanel *m_editor;
    UniformPanel *m_uniforms;
    BindingPanel *m_bindings;
    ObjectLoader *m_loader = nullptr; // the scene budget asks it for files before it exists
    MeshActions *m_meshActions;
    SceneActions *m_sceneActions;
    LessonActions *m_lessons = nullptr;
    ProbePanel *m_probe;
    PlotsPanel *m_plots;
    StatusLine *m_status;
    std::vector<QDockWidget *> m_panelDocks;
    QDockWidget *m_editorDock;
    QString m_glInfo;
    bool m_programReadsLight = true;
    DockLayout m_layout = DockLayout::Wide;
    bool m_widthsPending = false; // arranged before shown: the dock widths wait for show
    bool m_presentation = false;
    double m_tabShare = 1.4;           // the presentation tab font's share of the 100% font
    double m_scale = 1.0;              // the normal window's UI scale
    double m_presentationScale = 1.75; // presentation mode's
    QByteArray m_normalGeometry, m_normalState; // the window before presentation mode
    DockLayout m_normalLayout = DockLayout::Wide;
    QRect m_normalRect;
    bool m_normalUnsized = false;
    QRect m_available; // the screen area the window was fitted to
    QAction *m_presentationAction = nullptr;
    QActionGroup *m_scaleGroup = nullptr;
    QPointer<QDockWidget> m_forwardOnF6;    // bringForward()'s dock, while the panels wait
    QAction *m_panelsAction = nullptr;      // F6: the panels shown in presentation mode
    QAction *m_fadedArrowsAction = nullptr; // the probe's arrows faded over the surface
    ScreenBlank *m_blank = nullptr;
    SettingsAutosave *m_autosave; // saves shortly after each change, so a kill loses little
    ExercisePanel *m_exercisePanel;
    QDockWidget *m_exerciseDock;
    WorkCheck *m_workCheck;
    QAction *m_checkAction = nullptr;
    std::optional<Scene> m_ownScene; // the student's scene before the first case was shown
    // The program the listed outcome of Check my work was checked with (vertex, fragment).
    std::optional<std::pair<QString, QString>> m_checkedProgram;
    // Side B's shader files as read when chosen (path empty: none chosen).
    QString m_sideBPath, m_sideBVertex, m_sideBFragment, m_sideBName;
    UnsavedWorkAsker m_asker;             // none: nobody to ask
    bool m_sessionKeepsOnlySaved = false; // closing after Discard
};

} // namespace lb
