#pragma once
// Light: position (x, y, z) and w, the frame it is given in, and Ia, Id, Is.

#include "scene_panel.h"

#include <array>

class QComboBox;
class QDoubleSpinBox;

namespace lb {

class ColorEdit;

class LightPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit LightPanel(SceneDocument *document, QWidget *parent = nullptr);

    QDoubleSpinBox *coordinate(int i) const { return m_xyz[std::size_t(i)]; }
    QComboBox *wCombo() const { return m_w; }
    QComboBox *frameCombo() const { return m_frame; }
    ColorEdit *colorEdit(int i) const { return m_colors[std::size_t(i)]; } // Ia, Id, Is

protected:
    void refresh(const Scene &scene) override;

private:
    std::array<QDoubleSpinBox *, 3> m_xyz{};
    QComboBox *m_w;
    QComboBox *m_frame;
    std::array<ColorEdit *, 3> m_colors{};
};

} // namespace lb
