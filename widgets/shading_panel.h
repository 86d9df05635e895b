#pragma once
// Shading: Gouraud or Phong, the specular term, the projection, the terms and switches, and
// the comparison with a built-in program (side by side, wipe, difference; compare.h).

#include "scene_panel.h"

#include <array>

class QCheckBox;
class QComboBox;
class QSlider;

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
    QCheckBox *normalsByModelViewCheck() const { return m_normalsByModelView; }
    // Ambient, diffuse, specular.
    QCheckBox *termCheck(int i) const { return m_terms[std::size_t(i)]; }
    QComboBox *showCombo() const { return m_show; }
    QComboBox *compareModeCombo() const { return m_compareMode; }
    QComboBox *compareShadingCombo() const { return m_compareShading; }
    QComboBox *compareSpecularCombo() const { return m_compareSpecular; }
    QSlider *wipeSlider() const { return m_wipe; }

    // When the program on screen does its own shading (an edited built-in Gouraud program
    // stays Gouraud), the choice is greyed with `reason` as its tooltip; none: it is free.
    void setShadingFixed(bool fixed, const QString &reason);

protected:
    void refresh(const Scene &scene) override;

private:
    QComboBox *m_shading;
    QComboBox *m_specular;
    QComboBox *m_projection;
    QCheckBox *m_lighting;
    QCheckBox *m_vertexColors;
    QCheckBox *m_normalsByModelView;
    std::array<QCheckBox *, 3> m_terms{};
    QComboBox *m_show;
    QComboBox *m_compareMode;
    QComboBox *m_compareShading;
    QComboBox *m_compareSpecular;
    QSlider *m_wipe;
    QString m_shadingTip;
};

} // namespace lb
