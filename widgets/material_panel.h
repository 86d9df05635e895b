#pragma once
// Material: Ka, Kd, Ks and the shininess (log-scale slider beside a number box).

#include "scene_panel.h"

#include <array>

class QDoubleSpinBox;
class QSlider;

namespace lb {

class ColorEdit;

class MaterialPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit MaterialPanel(SceneDocument *document, QWidget *parent = nullptr);

    ColorEdit *colorEdit(int i) const { return m_colors[std::size_t(i)]; } // Ka, Kd, Ks
    QSlider *shininessSlider() const { return m_slider; }
    QDoubleSpinBox *shininessBox() const { return m_box; }

    // The slider runs 0..kSliderSteps over shininess 1..1000 on a log scale.
    static constexpr int kSliderSteps = 1000;
    static int sliderPosition(float shininess);
    static float shininessAt(int position);

protected:
    void refresh(const Scene &scene) override;

private:
    std::array<ColorEdit *, 3> m_colors{};
    QSlider *m_slider;
    QDoubleSpinBox *m_box;
};

} // namespace lb
