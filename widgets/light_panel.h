#pragma once
// Lights: up to four, one at a time (the tabs): on/off, position (x, y, z) and w, the frame it
// is given in, and Ia, Id, Is.

#include "scene_panel.h"

#include <array>

class QCheckBox;
class QComboBox;
class QTabBar;
class QDoubleSpinBox;

namespace lb {

class ColorEdit;

class LightPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit LightPanel(SceneDocument *document, QWidget *parent = nullptr);

    QTabBar *lightTabs() const { return m_tabs; }
    int currentLight() const; // 0 for light 1
    void setCurrentLight(int index);
    QCheckBox *enabledCheck() const { return m_enabled; }
    QDoubleSpinBox *coordinate(int i) const { return m_xyz[std::size_t(i)]; }
    QComboBox *wCombo() const { return m_w; }
    QComboBox *frameCombo() const { return m_frame; }
    QComboBox *frameObjectCombo() const { return m_frameObject; }
    ColorEdit *colorEdit(int i) const { return m_colors[std::size_t(i)]; }             // Ia, Id, Is
    QDoubleSpinBox *attenuation(int i) const { return m_attenuation[std::size_t(i)]; } // kc..
    QDoubleSpinBox *spotAxis(int i) const { return m_spotAxis[std::size_t(i)]; }
    QDoubleSpinBox *spotCutoff() const { return m_spotCutoff; }
    QDoubleSpinBox *spotExponent() const { return m_spotExponent; }

protected:
    void refresh(const Scene &scene) override;

protected:
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void nameTabs();
    // The "Of object" choices, when the objects' names changed.
    void refreshObjectNames(const Scene &scene);
    Light &current(Scene &scene) const { return scene.lights[std::size_t(currentLight())]; }

    QTabBar *m_tabs;
    QCheckBox *m_enabled;
    std::array<QDoubleSpinBox *, 3> m_xyz{};
    QComboBox *m_w;
    QComboBox *m_frame;
    QComboBox *m_frameObject; // the object an object-frame light belongs to
    std::array<ColorEdit *, 3> m_colors{};
    std::array<QDoubleSpinBox *, 3> m_attenuation{};
    std::array<QDoubleSpinBox *, 3> m_spotAxis{};
    QDoubleSpinBox *m_spotCutoff;
    QDoubleSpinBox *m_spotExponent;
};

} // namespace lb
