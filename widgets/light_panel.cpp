#include "light_panel.h"

#include "narrow_forms.h"

#include "color_edit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QTabBar>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lb {

namespace {
// Ia, Id, Is: the rows the colour edits show and change.
const char *const kLightColourKeys[3] = {"ia", "id", "is"};
// The light's row of the lighting model's table (lighting_parameters.h).
const LightingParameter &lightRow(const char *key)
{
    return *lightingParameter(ParameterOwner::Light, key);
}
} // namespace

LightPanel::LightPanel(SceneDocument *document, QWidget *parent)
    : ScenePanel(document, ScenePart::Lights, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_tabs = new QTabBar(this);
    m_tabs->setExpanding(false);
    m_tabs->setDrawBase(false);
    for (int i = 0; i < kMaxLights; ++i) {
        m_tabs->addTab(tr("Light %1").arg(i + 1));
        m_tabs->setAccessibleTabName(i, m_tabs->tabText(i));
    }
    m_tabs->setToolTip(tr("Up to four lights; their terms add up. A shader that declares one "
                          "light (not an array) reads light 1"));
    connect(m_tabs, &QTabBar::currentChanged, this, [this] { refreshNow(); });
    // The object list only names the objects a light may belong to: an object turning 60
    // times a second does not refresh the whole panel.
    connect(document, &SceneDocument::changed, this, [this](SceneParts parts) {
        if (parts & ScenePart::Object)
            refreshObjectNames(m_document->scene());
    });
    form->addRow(m_tabs);

    //: the light is switched on (a check box)
    m_enabled = new QCheckBox(tr("On"), this);
    m_enabled->setToolTip(tr("uLightEnabled[i]: a light switched off adds nothing (its colours "
                             "go to shaders as black)"));
    connect(m_enabled, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { current(s).enabled = on; }); });
    feeds(m_enabled, {Semantic::LightEnabled, Semantic::LightAmbient, Semantic::LightDiffuse,
                      Semantic::LightSpecular});
    //: the row of the light's on/off switch
    form->addRow(tr("Light"), m_enabled);
    const char *axes[3] = {"x", "y", "z"};
    auto *xyzRow = new WrapRow;
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *spin =
            makeSpin(lightRow("position"), lightRow("position").toolTipText().arg(axes[i]));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
            edit([&](Scene &s) { current(s).position[i] = float(v); });
        });
        m_xyz[std::size_t(i)] = spin;
        feeds(spin, lightRow("position").semantics);
        xyzRow->addWidget(spin);
    }
    form->addRow(tr("Position"), xyzRow);

    //: w is the light position's 4th (homogeneous) coordinate: a symbol, not a word
    m_w = makeCombo({tr("w = 1: point light"), tr("w = 0: directional")},
                    tr("lightPosition.w: 1 puts the light at (x, y, z); 0 makes (x, y, z) the "
                       "direction towards a light at infinity"));
    connect(m_w, &QComboBox::currentIndexChanged, this, [this](int index) {
        edit([&](Scene &s) {
            current(s).position.w = index == 0 ? 1.0f : 0.0f;
            // A directional light needs a direction.
            if (current(s).position.w == 0.0f && glm::vec3(current(s).position) == glm::vec3(0.0f))
                current(s).position.z = 1.0f;
        });
    });
    feeds(m_w, {Semantic::LightPosition, Semantic::LightPositionEye});
    //: a light's type: point or directional
    form->addRow(tr("Type"), m_w);

    m_frame =
        makeCombo({tr("Camera: moves with the eye"), tr("World: fixed in the scene"),
                   tr("Object: turns with the model")},
                  tr("Frame lightPosition is given in. Camera: used as is (variant I); "
                     "world: mView / mViewNormals (II); object: mModelView / mNormals (III)"));
    connect(m_frame, &QComboBox::currentIndexChanged, this,
            [this](int index) { edit([&](Scene &s) { current(s).frame = LightFrame(index); }); });
    feeds(m_frame, {Semantic::LightFrame, Semantic::LightPositionEye});
    m_frameObject = makeCombo({}, tr("The object whose frame an object-frame light is given in: "
                                     "the light turns and moves with it, and lights every "
                                     "object from there"));
    connect(m_frameObject, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index >= 0)
            edit([&](Scene &s) { current(s).object = index; });
    });
    feeds(m_frameObject, {Semantic::LightPosition, Semantic::LightPositionEye});
    //: the coordinate frame the light's position is given in
    form->addRow(tr("Frame"), m_frame);
    //: the object whose frame an object-frame light is given in
    form->addRow(tr("Of object"), m_frameObject);

    for (int i = 0; i < 3; ++i) {
        const LightingParameter &p = lightRow(kLightColourKeys[i]);
        const QString symbol = QString::fromLatin1(p.symbol);
        auto *colour = new ColorEdit(symbol, this);
        colour->setToolTip(p.toolTipText().arg(symbol, namesOf(p.semantics)));
        connect(colour, &ColorEdit::colorChanged, this, [this, i](const glm::vec3 &c) {
            edit([&](Scene &s) {
                std::copy(&c.x, &c.x + 3, lightRow(kLightColourKeys[i]).numbers(current(s)));
            });
        });
        m_colors[std::size_t(i)] = colour;
        feeds(colour, p.semantics);
        form->addRow(symbol, colour);
    }

    // OpenGL 2.1's attenuation and spotlight (issue 15): both scale all three terms.
    const char *kNames[3] = {"kc", "kl", "kq"};
    auto *attenuationRow = new WrapRow;
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *spin = makeSpin(
            lightRow("attenuation"), lightRow("attenuation").toolTipText().arg(axes[i], kNames[i]));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
            edit([&](Scene &s) {
                glm::vec3 k = current(s).attenuation;
                k[i] = float(v);
                // All three 0 would make the light infinite; all three under what the boxes
                // show (2 decimals) would leave a blinding light behind "0.00 0.00 0.00".
                if (std::max({k.x, k.y, k.z}) >= 0.005f)
                    current(s).attenuation = k;
            });
            refreshNow(); // a refused edit changes nothing: show the value that holds
        });
        m_attenuation[std::size_t(i)] = spin;
        feeds(spin, lightRow("attenuation").semantics);
        attenuationRow->addWidget(spin);
    }
    form->addRow(tr("Atten. kc kl kq"), attenuationRow);

    auto *axisRow = new WrapRow;
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *spin = makeSpin(lightRow("spot.direction"),
                                        lightRow("spot.direction").toolTipText().arg(axes[i]));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
            edit([&](Scene &s) {
                glm::vec3 d = current(s).spot.direction;
                d[i] = float(v);
                if (lightRow("spot.direction").refusal(&d.x).isEmpty()) // an axis needs a direction
                    current(s).spot.direction = d;
            });
            refreshNow();
        });
        m_spotAxis[std::size_t(i)] = spin;
        feeds(spin, lightRow("spot.direction").semantics);
        axisRow->addWidget(spin);
    }
    form->addRow(tr("Spot axis"), axisRow);

    auto *spotRow = new WrapRow;
    m_spotCutoff = makeSpin(lightRow("spot.cutoff"), lightRow("spot.cutoff").toolTipText());
    m_spotCutoff->setSuffix(QString::fromUtf8("°"));
    connect(m_spotCutoff, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit([&](Scene &s) { current(s).spot.cutoffDegrees = float(v); });
    });
    feeds(m_spotCutoff, lightRow("spot.cutoff").semantics);
    m_spotExponent = makeSpin(lightRow("spot.exponent"), lightRow("spot.exponent").toolTipText());
    connect(m_spotExponent, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { edit([&](Scene &s) { current(s).spot.exponent = float(v); }); });
    feeds(m_spotExponent, lightRow("spot.exponent").semantics);
    spotRow->addWidget(m_spotCutoff);
    spotRow->addWidget(m_spotExponent);
    //: the spotlight's cutoff angle and exponent
    form->addRow(tr("Spot cutoff, exp"), spotRow);

    addResetButton(form, tr("Reset light"),
                   tr("This light's defaults; light 1's are the slides' (0, 1.8, 1.3, 1) in "
                      "world coordinates"),
                   [this](Scene &s) { current(s) = defaultLights()[std::size_t(currentLight())]; });
    refreshNow();
}

void LightPanel::resizeEvent(QResizeEvent *event)
{
    ScenePanel::resizeEvent(event);
    nameTabs();
}

void LightPanel::changeEvent(QEvent *event)
{
    ScenePanel::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        nameTabs();
}

void LightPanel::nameTabs()
{
    // "Light 1" to "Light 4" where all four fit, else their numbers: four tabs in sight, none
    // behind the bar's arrows (a column of 38% at 200%).
    for (int i = 0; i < kMaxLights; ++i)
        m_tabs->setTabText(i, tr("Light %1").arg(i + 1));
    const QMargins margins = layout()->contentsMargins();
    if (m_tabs->sizeHint().width() <= width() - margins.left() - margins.right())
        return;
    for (int i = 0; i < kMaxLights; ++i)
        m_tabs->setTabText(i, QString::number(i + 1)); // the accessible name stays whole
}

int LightPanel::currentLight() const
{
    return std::clamp(m_tabs->currentIndex(), 0, kMaxLights - 1);
}

void LightPanel::setCurrentLight(int index)
{
    m_tabs->setCurrentIndex(index);
}

void LightPanel::refreshObjectNames(const Scene &scene)
{
    QStringList names;
    for (const ObjectSettings &o : scene.objects)
        names << displayName(o);
    QStringList shown;
    for (int i = 0; i < m_frameObject->count(); ++i)
        shown << m_frameObject->itemText(i);
    if (shown == names)
        return;
    const QSignalBlocker block(m_frameObject);
    m_frameObject->clear();
    m_frameObject->addItems(names);
    const Light &light = scene.lights[std::size_t(currentLight())];
    m_frameObject->setCurrentIndex(std::clamp(light.object, 0, int(names.size()) - 1));
}

void LightPanel::refresh(const Scene &scene)
{
    // Lights that are off have grey tabs.
    for (int i = 0; i < kMaxLights; ++i)
        m_tabs->setTabTextColor(i, scene.lights[std::size_t(i)].enabled
                                       ? palette().color(QPalette::WindowText)
                                       : palette().color(QPalette::Disabled, QPalette::WindowText));
    const Light &light = scene.lights[std::size_t(currentLight())];
    {
        const QSignalBlocker block(m_enabled);
        m_enabled->setChecked(light.enabled);
    }
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker block(m_xyz[std::size_t(i)]);
        m_xyz[std::size_t(i)]->setValue(double(light.position[i]));
        m_colors[std::size_t(i)]->setColor(
            glm::make_vec3(lightRow(kLightColourKeys[i]).numbers(light)));
    }
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker block(m_attenuation[std::size_t(i)]),
            blockAxis(m_spotAxis[std::size_t(i)]);
        m_attenuation[std::size_t(i)]->setValue(double(light.attenuation[i]));
        m_spotAxis[std::size_t(i)]->setValue(double(light.spot.direction[i]));
        // A directional light is not attenuated: its numbers are kept but have no effect.
        setApplies(m_attenuation[std::size_t(i)], light.position.w != 0.0f);
    }
    const bool spot = light.spot.cutoffDegrees < limits::kMaxSpotCutoff;
    for (QDoubleSpinBox *spin : m_spotAxis)
        setApplies(spin, spot);
    setApplies(m_spotExponent, spot);
    const QSignalBlocker b1(m_w), b2(m_frame), b3(m_spotCutoff), b4(m_spotExponent),
        b5(m_frameObject);
    refreshObjectNames(scene);
    m_frameObject->setCurrentIndex(std::clamp(light.object, 0, m_frameObject->count() - 1));
    setApplies(m_frameObject, light.frame == LightFrame::Object);
    m_spotCutoff->setValue(double(light.spot.cutoffDegrees));
    m_spotExponent->setValue(double(light.spot.exponent));
    m_w->setCurrentIndex(light.position.w == 0.0f ? 1 : 0);
    m_frame->setCurrentIndex(int(light.frame));
}

} // namespace lb
