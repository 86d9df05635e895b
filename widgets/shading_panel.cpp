#include "shading_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QSignalBlocker>

namespace lb {

ShadingPanel::ShadingPanel(SceneDocument *document, QWidget *parent) : ScenePanel(document, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    m_shading = makeCombo({tr("Gouraud (per vertex)"), tr("Phong (per fragment)")},
                          tr("Gouraud: the model runs in the vertex shader and colours are "
                             "interpolated; Phong: N, L, V are interpolated and the model runs "
                             "for every fragment (key G)"));
    connect(m_shading, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.shading = Shading(i); }); });
    form->addRow(tr("Shading"), m_shading);

    m_specular = makeCombo({tr("Phong: (R\u00b7V)^n"), tr("Blinn-Phong: (N\u00b7H)^n")},
                           tr("R = reflect(-L, N), the mirrored light direction; "
                              "H = normalize(L + V), the half vector (key B)"));
    connect(m_specular, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.specular = SpecularModel(i); }); });
    feeds(m_specular, {Semantic::SpecularModel}, "uSpecularModel");
    form->addRow(tr("Specular"), m_specular);

    m_projection = makeCombo({tr("Perspective: V = -posC"), tr("Orthographic: V = (0,0,1)")},
                             tr("mProjection, and the view vector V that matches it (key P)"));
    connect(m_projection, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.shading.projection = Projection(i); }); });
    feeds(m_projection, {Semantic::Projection, Semantic::ProjectionKind},
          "mProjection or uProjectionMatrix");
    form->addRow(tr("Projection"), m_projection);

    auto makeCheck = [this, form](const QString &label, const QString &tip,
                                  bool ShadingSettings::*member) {
        auto *check = new QCheckBox(label, this);
        check->setToolTip(tip);
        connect(check, &QCheckBox::toggled, this,
                [this, member](bool on) { edit([&](Scene &s) { s.shading.*member = on; }); });
        form->addRow(check);
        return check;
    };
    m_lighting = makeCheck(tr("Lighting"), tr("uEnableLighting: off shows Kd unlit (key L)"),
                           &ShadingSettings::lighting);
    m_vertexColors = makeCheck(tr("Vertex colours"),
                               tr("Multiply ambient and diffuse by the vertex colour (vColor)"),
                               &ShadingSettings::vertexColors);
    m_texture = makeCheck(tr("Texture"),
                          tr("uEnableTexture: multiply ambient and diffuse by the texture "
                             "(uSampler): the mesh file's diffuse texture, or the checker"),
                          &ShadingSettings::texture);
    feeds(m_lighting, {Semantic::EnableLighting}, "uEnableLighting");
    feeds(m_vertexColors, {Semantic::EnableVertexColor}, "uEnableVertexColor");
    feeds(m_texture, {Semantic::EnableTexture}, "uEnableTexture");

    addResetButton(form, tr("Reset shading"),
                   tr("Phong shading, Blinn-Phong specular, perspective, lighting on"),
                   [](Scene &s) { s.shading = ShadingSettings{}; });
    refreshNow();
}

void ShadingPanel::refresh(const Scene &scene)
{
    const QSignalBlocker b1(m_shading), b2(m_specular), b3(m_projection), b4(m_lighting),
        b5(m_vertexColors), b6(m_texture);
    m_shading->setCurrentIndex(int(scene.shading.shading));
    m_specular->setCurrentIndex(int(scene.shading.specular));
    m_projection->setCurrentIndex(int(scene.shading.projection));
    m_lighting->setChecked(scene.shading.lighting);
    m_vertexColors->setChecked(scene.shading.vertexColors);
    m_texture->setChecked(scene.shading.texture);
}

} // namespace lb
