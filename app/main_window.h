#pragma once
// The workbench window: the viewport in the centre, the Light and Material panels docked on
// the left, Shading and Object on the right. Scene, window layout and docks are kept in
// QSettings and come back at the next start.

#include "program_build.h"
#include "scene_document.h"
#include "shader_document.h"

#include <QMainWindow>
#include <QTimer>

class QLabel;
class QSettings;

namespace lb {

class EditorPanel;
class LightPanel;
class MaterialPanel;
class MeshActions;
class ObjectLoader;
class ObjectPanel;
class ProbePanel;
class SceneActions;
class ShadingPanel;
class UniformPanel;
class Viewport;

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
    ObjectLoader *objectLoader() const { return m_loader; }
    MeshActions *meshActions() const { return m_meshActions; }
    SceneActions *sceneActions() const { return m_sceneActions; }
    ProbePanel *probePanel() const { return m_probe; }

    void saveSettings();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void buildMenus();
    void updateStatus();
    void showProgramUsage(const ProgramBuild &build);

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
    ObjectLoader *m_loader;
    MeshActions *m_meshActions;
    SceneActions *m_sceneActions;
    ProbePanel *m_probe;
    QLabel *m_glLabel;
    QTimer m_saveTimer; // saves the scene shortly after each change, so a kill loses little
};

} // namespace lb
