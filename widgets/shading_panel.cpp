#include "shading_panel.h"

#include "narrow_forms.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>

#include <array>
#include <cmath>
#include <tuple>

namespace lb {

ShadingPanel::ShadingPanel(SceneDocument *document, QWidget *parent)
    : ScenePanel(document, ScenePart::Shading | ScenePart::Compare, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    m_shading = makeCombo(
        {tr("Gouraud (per vertex)"), tr("Phong (per fragment)"), tr("Flat (per triangle)")},
        tr("Gouraud: the model runs in the vertex shader and colours are "
           "interpolated; Phong: N, L, V are interpolated and the model runs "
           "for every fragment; flat: each triangle takes the colour of its "
           "last (provoking) vertex (key G: Gouraud / Phong)"));
    connect(m_shading, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.shading = Shading(i); }); });
    form->addRow(tr("Shading"), m_shading);
    m_shadingTip = m_shading->toolTip();

    // The models in their table's order (lighting_models.h), each item's data its model.
    const auto modelItems = [](QComboBox *combo, QString (*label)(SpecularModel)) {
        for (const SpecularModelRow &row : specularModels())
            combo->addItem(label(row.model), int(row.model));
    };
    m_specular = makeCombo({}, tr("R = reflect(-L, N), the mirrored light direction; "
                                  "H = normalize(L + V), the half vector (key B)"));
    modelItems(m_specular, [](SpecularModel model) {
        const SpecularModelRow &row = specularModel(model);
        //: the specular model's name and its factor: "Phong: (R·V)^n"
        return tr("%1: %2").arg(QString::fromUtf8(row.name), QString::fromUtf8(row.factor));
    });
    connect(m_specular, &QComboBox::currentIndexChanged, this, [this] {
        edit([&](Scene &s) {
            s.shading.specular = SpecularModel(m_specular->currentData().toInt());
        });
    });
    feeds(m_specular, {Semantic::SpecularModel});
    //: the row of the specular term's choice (Phong or Blinn-Phong)
    form->addRow(tr("Specular"), m_specular);

    m_projection = makeCombo({tr("Perspective: V = -posC"), tr("Orthographic: V = (0,0,1)")},
                             tr("mProjection, and the view vector V that matches it (key P)"));
    connect(m_projection, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.projection = Projection(i); }); });
    feeds(m_projection, {Semantic::Projection, Semantic::ProjectionKind});
    form->addRow(tr("Projection"), m_projection);

    auto makeCheck = [this, form](const QString &label, const QString &tip,
                                  bool ShadingSettings::*member) {
        auto *check = new WrapCheckBox(label, this);
        check->setToolTip(tip);
        connect(check, &QCheckBox::toggled, this,
                [this, member](bool on) { edit([&](Scene &s) { s.shading.*member = on; }); });
        form->addRow(check);
        return check;
    };
    //: what the surface shows: the lit colour, or a vector (N, L, V, H, R) or number as colour
    m_show = makeCombo({tr("Colour (lit)"), tr("N as colour"), tr("L as colour"), tr("V as colour"),
                        tr("H as colour"), tr("R as colour"), tr("N\u00b7L as grey"),
                        tr("Specular factor as grey"), tr("Attenuation as grey")},
                       tr("uShow: the model taken apart. Vectors as 0.5\u00b7v + 0.5 (x red, y "
                          "green, z blue), numbers as grey; L, H, R and the numbers are light "
                          "1's (with several lights on too)"));
    connect(m_show, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.show = ShowChoice(i); }); });
    feeds(m_show, {Semantic::Show});
    //: the row of the Show choice (what the surface shows)
    form->addRow(tr("Show"), m_show);

    //: a switch: the lighting model on, or Kd unlit
    m_lighting = makeCheck(tr("Lighting"), tr("uEnableLighting: off shows Kd unlit (key L)"),
                           &ShadingSettings::lighting);
    m_vertexColors = makeCheck(tr("Vertex colours"),
                               tr("Multiply ambient and diffuse by the vertex colour (vColor)"),
                               &ShadingSettings::vertexColors);
    // The terms on one row: the model taken apart, each term alone or in pairs.
    auto *termsRow = new WrapRow(WrapRow::Room::Left);
    const std::tuple<QString, QString, bool TermSwitches::*, Semantic> terms[] = {
        {tr("Ambient"), tr("Ia·Ka: uEnableAmbient (key A)"), &TermSwitches::ambient,
         Semantic::EnableAmbient},
        {tr("Diffuse"), tr("Id·Kd·max(N·L, 0): uEnableDiffuse (key D)"), &TermSwitches::diffuse,
         Semantic::EnableDiffuse},
        {tr("Specular"), tr("Is·Ks·(R·V or N·H)^n: uEnableSpecular (key S)"),
         &TermSwitches::specular, Semantic::EnableSpecular}};
    for (std::size_t i = 0; i < 3; ++i) {
        const auto &[label, tip, member, semantic] = terms[i];
        auto *check = new QCheckBox(label, this);
        check->setToolTip(tip);
        connect(check, &QCheckBox::toggled, this, [this, member = member](bool on) {
            edit([&](Scene &s) { s.shading.terms.*member = on; });
        });
        feeds(check, {semantic});
        termsRow->addWidget(check);
        m_terms[i] = check;
    }
    //: the row of the ambient, diffuse and specular terms' switches
    form->addRow(tr("Terms"), termsRow);
    feeds(m_lighting, {Semantic::EnableLighting});
    feeds(m_vertexColors, {Semantic::EnableVertexColor});
    m_normalsByModelView = makeCheck(
        tr("Normals by the model-view (wrong)"),
        tr("Transform normals by mModelView instead of its inverse transpose, to see why the "
           "normal matrix exists: under a non-uniform scale the normals tilt"),
        &ShadingSettings::normalsByModelView);
    feeds(m_normalsByModelView, {Semantic::Normals});

    auto *compareTitle = new QLabel(tr("<b>Compare</b> side A with side B"), this);
    compareTitle->setWordWrap(true);
    compareTitle->setToolTip(tr("Side A is the program on screen (the editor's); side B is the "
                                "built-in program with the choices below, a shader pair from "
                                "files, or an open exercise's reference; one camera"));
    form->addRow(compareTitle);
    m_sideB = new QLabel(this);
    m_sideB->setWordWrap(true);
    m_sideB->setTextFormat(Qt::PlainText);
    m_sideBFiles = new QToolButton(this);
    m_sideBFiles->setText(tr("Files..."));
    m_sideBFiles->setToolTip(tr("Side B draws a shader pair from files (NAME.vert and "
                                "NAME.frag), e.g. last week's solution"));
    connect(m_sideBFiles, &QToolButton::clicked, this, &ShadingPanel::sideBFilesRequested);
    m_sideBClear = new QToolButton(this);
    m_sideBClear->setText(QString::fromUtf8("\u00d7"));
    m_sideBClear->setToolTip(tr("Stop using these files: side B draws what it drew before them"));
    connect(m_sideBClear, &QToolButton::clicked, this, &ShadingPanel::sideBClearRequested);
    // In a widget of its own: as a nested layout, the form gave the row the buttons' height
    // and cut a description that wraps (at 200%, "the exercise's reference" in two lines).
    auto *sideB = new QWidget(this);
    auto *sideBRow = new QHBoxLayout(sideB);
    sideBRow->setContentsMargins(0, 0, 0, 0);
    sideBRow->addWidget(m_sideB, 1);
    sideBRow->addWidget(m_sideBFiles);
    sideBRow->addWidget(m_sideBClear);
    //: the program side B of the compare view draws (A and B are the two sides)
    form->addRow(tr("B program"), sideB);
    //: the compare view is off (A alone)
    m_compareMode = makeCombo({tr("Off"), tr("Side by side"), tr("Wipe"), tr("Difference |A - B|")},
                              tr("Side by side: A left, B right; wipe: drag the line in the view; "
                                 "difference: |A - B| as a heat map (key C cycles)"));
    connect(m_compareMode, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.compare.mode = CompareMode(i); }); });
    //: the compare view (off, side by side, wipe, difference); not the menu, not the camera
    form->addRow(tr("View"), m_compareMode);
    //: side B's shading (B is the compare view's second side)
    m_compareShading = makeCombo({tr("B: Gouraud"), tr("B: Phong"), tr("B: Flat")},
                                 tr("Side B's shading: per vertex or per fragment"));
    connect(m_compareShading, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.compare.shading = Shading(i); }); });
    //: side B's shading (B is the compare view's second side)
    form->addRow(tr("B shading"), m_compareShading);
    m_compareSpecular = makeCombo({}, tr("Side B's specular term"));
    modelItems(m_compareSpecular, [](SpecularModel model) {
        //: side B's specular model (B is the compare view's second side): "B: Phong (R·V)"
        return tr("B: %1").arg(specularModelTitle(model));
    });
    connect(m_compareSpecular, &QComboBox::currentIndexChanged, this, [this] {
        edit([&](Scene &s) {
            s.compare.specular = SpecularModel(m_compareSpecular->currentData().toInt());
        });
    });
    //: side B's specular term (B is the compare view's second side)
    form->addRow(tr("B specular"), m_compareSpecular);
    for (QComboBox *combo : {m_compareShading, m_compareSpecular})
        combo->setProperty("ownTip", combo->toolTip());
    m_wipe = new QSlider(Qt::Horizontal, this);
    m_wipe->setRange(0, 1000);
    m_wipe->setToolTip(tr("Where the wipe divides A (left) from B (right)"));
    connect(m_wipe, &QSlider::valueChanged, this,
            [this](int v) { edit([&](Scene &s) { s.compare.wipe = float(v) / 1000.0f; }); });
    //: the row of the slider that places the wipe's dividing line
    form->addRow(tr("Wipe"), m_wipe);

    addResetButton(form, tr("Reset shading"),
                   tr("Phong shading, Blinn-Phong specular, perspective, lighting on"),
                   [](Scene &s) {
                       s.shading = ShadingSettings{};
                       s.compare = CompareSettings{};
                   });
    setSideB(tr("the built-in program"), {}, false); // shows the scene too
}

void ShadingPanel::setShadingFixed(bool fixed, const QString &reason)
{
    m_shading->setEnabled(!fixed);
    m_shading->setToolTip(fixed ? reason : m_shadingTip);
}

void ShadingPanel::setSideB(const QString &description, const QString &fixed, bool clearable)
{
    m_sideB->setText(description);
    m_sideB->setToolTip(description);
    m_sideBClear->setVisible(clearable);
    m_sideBFixed = fixed;
    for (QComboBox *combo : {m_compareShading, m_compareSpecular})
        combo->setToolTip(fixed.isEmpty() ? combo->property("ownTip").toString() : fixed);
    refreshNow();
}

void ShadingPanel::refresh(const Scene &scene)
{
    const QSignalBlocker b1(m_shading), b2(m_specular), b3(m_projection), b4(m_lighting),
        b5(m_vertexColors), b7(m_normalsByModelView), b8(m_compareMode), b9(m_compareShading),
        b10(m_compareSpecular), b11(m_wipe), b12(m_terms[0]), b13(m_terms[1]), b14(m_terms[2]),
        b15(m_show);
    m_show->setCurrentIndex(int(scene.shading.show));
    m_shading->setCurrentIndex(int(scene.shading.shading));
    m_specular->setCurrentIndex(m_specular->findData(int(scene.shading.specular)));
    m_projection->setCurrentIndex(int(scene.shading.projection));
    m_lighting->setChecked(scene.shading.lighting);
    m_terms[0]->setChecked(scene.shading.terms.ambient);
    m_terms[1]->setChecked(scene.shading.terms.diffuse);
    m_terms[2]->setChecked(scene.shading.terms.specular);
    for (QCheckBox *check : m_terms)
        setApplies(check, scene.shading.lighting);
    m_vertexColors->setChecked(scene.shading.vertexColors);
    m_normalsByModelView->setChecked(scene.shading.normalsByModelView);
    m_compareMode->setCurrentIndex(int(scene.compare.mode));
    m_compareShading->setCurrentIndex(int(scene.compare.shading));
    m_compareSpecular->setCurrentIndex(m_compareSpecular->findData(int(scene.compare.specular)));
    m_wipe->setValue(int(std::lround(scene.compare.wipe * 1000.0f)));
    const bool comparing = scene.compare.mode != CompareMode::Off;
    m_compareShading->setEnabled(comparing && m_sideBFixed.isEmpty());
    m_compareSpecular->setEnabled(comparing && m_sideBFixed.isEmpty());
    m_wipe->setEnabled(scene.compare.mode == CompareMode::Wipe);
}

} // namespace lb
