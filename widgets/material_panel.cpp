#include "material_panel.h"

#include "color_edit.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace lb {

namespace {
glm::vec3 Material::*const kMaterialColours[3] = {&Material::ka, &Material::kd, &Material::ks};
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
    const char *symbols[3] = {"Ka", "Kd", "Ks"};
    const Semantic semantics[3] = {Semantic::MaterialAmbient, Semantic::MaterialDiffuse,
                                   Semantic::MaterialSpecular};
    // Whole sentences, one a term (the term's word was slotted in untranslated).
    //: %1 the symbol (Ka, Kd, Ks); %2 the uniforms that carry it
    const QString tips[3] = {tr("%1 (%2): the material's ambient reflection coefficients"),
                             tr("%1 (%2): the material's diffuse reflection coefficients"),
                             tr("%1 (%2): the material's specular reflection coefficients")};
    for (int i = 0; i < 3; ++i) {
        auto *colour = new ColorEdit(symbols[i], this);
        colour->setToolTip(tips[i].arg(symbols[i], namesOf({semantics[i]})));
        connect(colour, &ColorEdit::colorChanged, this, [this, i](const glm::vec3 &c) {
            edit([&](Scene &s) { s.selectedObject().material.*kMaterialColours[i] = c; });
        });
        m_colors[std::size_t(i)] = colour;
        feeds(colour, {semantics[i]});
        form->addRow(symbols[i], colour);
    }

    const QString tip = tr("shininess: the specular exponent n in (R.V)^n or (N.H)^n; higher "
                           "gives a smaller, sharper highlight");
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setRange(0, kSliderSteps);
    m_slider->setToolTip(tip);
    m_box = makeSpin(limits::kMinShininess, limits::kMaxShininess, 1, 1.0, tip);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        edit([&](Scene &s) { s.selectedObject().material.shininess = shininessAt(position); });
    });
    connect(m_box, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit([&](Scene &s) { s.selectedObject().material.shininess = float(v); });
    });
    feeds(m_slider, {Semantic::Shininess});
    feeds(m_box, {Semantic::Shininess});
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
        m_colors[std::size_t(i)]->setColor(scene.selectedObject().material.*kMaterialColours[i]);
    const QSignalBlocker b1(m_slider), b2(m_box);
    m_slider->setValue(sliderPosition(scene.selectedObject().material.shininess));
    m_box->setValue(double(scene.selectedObject().material.shininess));
}

} // namespace lb
