#pragma once
// Shading: Gouraud or Phong, the specular term, the projection, and the three switches.

#include "scene_panel.h"

class QCheckBox;
class QComboBox;

namespace lb {

class ShadingPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit ShadingPanel(SceneDocument *document, QWidget *parent = nullptr);

    QComboBox *shadingCombo() const { return m_shading; }
    QComboBox *specularCombo() const { return m_specular; }
    QComboBox *projectionCombo() const { return m_projection; }
    QCheckBox *lightingCheck() const { return m_lighting; }
    QCheckBox *vertexColorsCheck() const { return m_vertexColors; }
    QCheckBox *textureCheck() const { return m_texture; }

protected:
    void refresh(const Scene &scene) override;

private:
    QComboBox *m_shading;
    QComboBox *m_specular;
    QComboBox *m_projection;
    QCheckBox *m_lighting;
    QCheckBox *m_vertexColors;
    QCheckBox *m_texture;
};

} // namespace lb
