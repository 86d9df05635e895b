#include "material_panel.h"

#include "color_edit.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
// Ka, Kd, Ks: the material's rows of the lighting model's table (lighting_parameters.h).
const char *const kMaterialColourKeys[3] = {"ka", "kd", "ks"};
const LightingParameter &materialRow(const char *key)
{
    return *lightingParameter(ParameterOwner::Material, key);
}
const double kLogRange = std::log(double(limits::kMaxShininess) / limits::kMinShininess);
} // namespace

int MaterialPanel::sliderPosition(float shininess)
{
    const double t = std::log(double(shininess) / limits::kMinShininess) / kLogRange;
    return int(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
}

float MaterialPanel::shininessAt(int position)
{
    return float(limits::kMinShininess * std::exp(kLogRange * position / kSliderSteps));
}

MaterialPanel::MaterialPanel(SceneDocument *document, QWidget *parent)
    : ScenePanel(document, ScenePart::Material, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (int i = 0; i < 3; ++i) {
        const LightingParameter &p = materialRow(kMaterialColourKeys[i]);
        const QString symbol = QString::fromLatin1(p.symbol);
        auto *colour = new ColorEdit(symbol, this);
        colour->setToolTip(p.toolTipText().arg(symbol, namesOf(p.semantics)));
        connect(colour, &ColorEdit::colorChanged, this, [this, i](const glm::vec3 &c) {
            edit([&](Scene &s) {
                std::copy(&c.x, &c.x + 3,
                          materialRow(kMaterialColourKeys[i]).numbers(s.selectedObject().material));
            });
        });
        m_colors[std::size_t(i)] = colour;
        feeds(colour, p.semantics);
        form->addRow(symbol, colour);
    }

    const LightingParameter &shininess = materialRow("shininess");
    const QString tip = shininess.toolTipText();
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setRange(0, kSliderSteps);
    m_slider->setToolTip(tip);
    m_box = makeSpin(shininess, tip);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        edit([&](Scene &s) { s.selectedObject().material.shininess = shininessAt(position); });
    });
    connect(m_box, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit([&](Scene &s) { s.selectedObject().material.shininess = float(v); });
    });
    feeds(m_slider, shininess.semantics);
    feeds(m_box, shininess.semantics);
    auto *row = new QHBoxLayout;
    row->addWidget(m_slider, 1);
    row->addWidget(m_box);
    form->addRow(tr("Shininess"), row);

    addResetButton(form, tr("Reset material"),
                   tr("The selected object's material back to the slides' red plastic: Ka = Kd = "
                      "(1, 0, 0), Ks = (1, 1, 1), n = 6"),
                   [](Scene &s) { s.selectedObject().material = Material{}; });
    refreshNow();
}

void MaterialPanel::refresh(const Scene &scene)
{
    for (int i = 0; i < 3; ++i)
        m_colors[std::size_t(i)]->setColor(glm::make_vec3(
            materialRow(kMaterialColourKeys[i]).numbers(scene.selectedObject().material)));
    const QSignalBlocker b1(m_slider), b2(m_box);
    m_slider->setValue(sliderPosition(scene.selectedObject().material.shininess));
    m_box->setValue(double(scene.selectedObject().material.shininess));
}

} // namespace lb
