#pragma once
// Object: the shape and its tessellation, rotation and (possibly non-uniform) scale per axis,
// and auto-rotate.

#include "scene_panel.h"

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace lb {

class ObjectPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit ObjectPanel(SceneDocument *document, QWidget *parent = nullptr);

    QComboBox *shapeCombo() const { return m_shape; }
    QSpinBox *tessellationBox() const { return m_tessellation; }
    QDoubleSpinBox *rotation(int i) const { return m_rotation[std::size_t(i)]; }
    QDoubleSpinBox *scale(int i) const { return m_scale[std::size_t(i)]; }
    QCheckBox *autoRotateCheck() const { return m_autoRotate; }

protected:
    void refresh(const Scene &scene) override;

private:
    QComboBox *m_shape;
    QSpinBox *m_tessellation;
    std::array<QDoubleSpinBox *, 3> m_rotation{};
    std::array<QDoubleSpinBox *, 3> m_scale{};
    QCheckBox *m_autoRotate;
};

} // namespace lb
