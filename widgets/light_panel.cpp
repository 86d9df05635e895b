#include "light_panel.h"

#include "color_edit.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace lb {

namespace {
glm::vec3 LightColors::*const kColourMembers[3] = {&LightColors::ia, &LightColors::id,
                                                   &LightColors::is};
}

LightPanel::LightPanel(SceneDocument *document, QWidget *parent) : ScenePanel(document, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const char *axes[3] = {"x", "y", "z"};
    auto *xyzRow = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *spin =
            makeSpin(-limits::kMaxCoordinate, limits::kMaxCoordinate, 2, 0.1,
                     tr("lightPosition.%1: the light's %1 in the chosen frame").arg(axes[i]));
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, i](double v) { edit([&](Scene &s) { s.light.position[i] = float(v); }); });
        m_xyz[std::size_t(i)] = spin;
        feeds(spin, {Semantic::LightPosition, Semantic::LightPositionEye},
              "lightPosition or uLightPosition");
        xyzRow->addWidget(spin);
    }
    form->addRow(tr("Position"), xyzRow);

    m_w = makeCombo({tr("w = 1: point light"), tr("w = 0: directional")},
                    tr("lightPosition.w: 1 puts the light at (x, y, z); 0 makes (x, y, z) the "
                       "direction towards a light at infinity"));
    connect(m_w, &QComboBox::currentIndexChanged, this, [this](int index) {
        edit([&](Scene &s) {
            s.light.position.w = index == 0 ? 1.0f : 0.0f;
            // A directional light needs a direction.
            if (s.light.position.w == 0.0f && glm::vec3(s.light.position) == glm::vec3(0.0f))
                s.light.position.z = 1.0f;
        });
    });
    feeds(m_w, {Semantic::LightPosition, Semantic::LightPositionEye},
          "lightPosition or uLightPosition");
    form->addRow(tr("Type"), m_w);

    m_frame =
        makeCombo({tr("Camera: moves with the eye"), tr("World: fixed in the scene"),
                   tr("Object: turns with the model")},
                  tr("Frame lightPosition is given in. Camera: used as is (variant I); "
                     "world: mView / mViewNormals (II); object: mModelView / mNormals (III)"));
    connect(m_frame, &QComboBox::currentIndexChanged, this,
            [this](int index) { edit([&](Scene &s) { s.light.frame = LightFrame(index); }); });
    feeds(m_frame, {Semantic::LightFrame, Semantic::LightPositionEye},
          "uLightFrame or uLightPosition");
    form->addRow(tr("Frame"), m_frame);

    const char *symbols[3] = {"Ia", "Id", "Is"};
    const char *uniforms[3] = {"lightAmb", "lightDif", "lightSpe"};
    for (int i = 0; i < 3; ++i) {
        auto *colour = new ColorEdit(symbols[i], this);
        colour->setToolTip(tr("%1 (%2): the light's %3 intensity")
                               .arg(symbols[i], uniforms[i],
                                    i == 0   ? tr("ambient")
                                    : i == 1 ? tr("diffuse")
                                             : tr("specular")));
        connect(colour, &ColorEdit::colorChanged, this, [this, i](const glm::vec3 &c) {
            edit([&](Scene &s) { s.light.colors.*kColourMembers[i] = c; });
        });
        m_colors[std::size_t(i)] = colour;
        const Semantic semantics[3] = {Semantic::LightAmbient, Semantic::LightDiffuse,
                                       Semantic::LightSpecular};
        feeds(colour, {semantics[i]}, i == 1 ? "lightDif or uLightColor" : uniforms[i]);
        form->addRow(symbols[i], colour);
    }

    addResetButton(form, tr("Reset light"),
                   tr("The slides' light: (0, 1.8, 1.3, 1) in world coordinates"),
                   [](Scene &s) { s.light = Light{}; });
    refreshNow();
}

void LightPanel::refresh(const Scene &scene)
{
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker block(m_xyz[std::size_t(i)]);
        m_xyz[std::size_t(i)]->setValue(double(scene.light.position[i]));
        m_colors[std::size_t(i)]->setColor(scene.light.colors.*kColourMembers[i]);
    }
    const QSignalBlocker b1(m_w), b2(m_frame);
    m_w->setCurrentIndex(scene.light.position.w == 0.0f ? 1 : 0);
    m_frame->setCurrentIndex(int(scene.light.frame));
}

} // namespace lb
