#pragma once
// Shading: Gouraud or Phong, the specular term, the projection, the terms and switches, and
// the comparison of the program on screen (side A) with side B (side by side, wipe,
// difference; compare.h): the built-in program with its own choices, a shader pair from files,
// or an open exercise's reference.

#include "scene_panel.h"

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

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
    QLabel *sideBLabel() const { return m_sideB; }
    QToolButton *sideBFilesButton() const { return m_sideBFiles; }
    QToolButton *sideBClearButton() const { return m_sideBClear; }

    // What side B draws, in words ("the built-in program", "toon.vert + toon.frag"); `fixed`:
    // why its shading and specular choices do nothing (its program shades as it is written,
    // or an exercise fixes them), empty when they apply; `clearable`: the x button brings
    // back the side B before the files.
    void setSideB(const QString &description, const QString &fixed, bool clearable);

    // When the program on screen does its own shading (an edited built-in Gouraud program
    // stays Gouraud), the choice is greyed with `reason` as its tooltip; none: it is free.
    void setShadingFixed(bool fixed, const QString &reason);

signals:
    void sideBFilesRequested(); // "Files...": a shader pair for side B
    void sideBClearRequested(); // x: side B as it was before the files

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
    QLabel *m_sideB;
    QToolButton *m_sideBFiles, *m_sideBClear;
    QString m_shadingTip;
    QString m_sideBFixed; // why side B's choices do nothing; empty: they apply
};

} // namespace lb
