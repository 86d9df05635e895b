#include "object_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace lb {

ObjectPanel::ObjectPanel(SceneDocument *document, QWidget *parent) : ScenePanel(document, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    m_shape = makeCombo({tr("Cube (flat faces)"), tr("Sphere (smooth)"), tr("Torus"), tr("Plane")},
                        tr("The object: vPosition and vNormal come from this mesh"));
    connect(m_shape, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.object.shape = Shape(i); }); });
    form->addRow(tr("Shape"), m_shape);

    m_tessellation = new QSpinBox(this);
    m_tessellation->setRange(limits::kMinTessellation, limits::kMaxTessellation);
    m_tessellation->setKeyboardTracking(false);
    m_tessellation->setToolTip(tr("Subdivisions of the sphere, torus and plane. Few vertices "
                                  "show Gouraud's weakness: its highlight follows the vertices"));
    connect(m_tessellation, &QSpinBox::valueChanged, this,
            [this](int v) { edit([&](Scene &s) { s.object.tessellation = v; }); });
    form->addRow(tr("Tessellation"), m_tessellation);

    const char *axes[3] = {"X", "Y", "Z"};
    auto *rotationRow = new QHBoxLayout;
    auto *scaleRow = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *r = makeSpin(-360.0, 360.0, 1, 5.0,
                                     tr("Rotation about %1 in degrees (model matrix; applied X, "
                                        "then Y, then Z)")
                                         .arg(axes[i]));
        r->setWrapping(true);
        connect(r, &QDoubleSpinBox::valueChanged, this, [this, i](double v) {
            edit([&](Scene &s) { s.object.rotationDegrees[i] = float(v); });
        });
        m_rotation[std::size_t(i)] = r;
        rotationRow->addWidget(r);

        QDoubleSpinBox *sc = makeSpin(limits::kMinScale, limits::kMaxScale, 2, 0.1,
                                      tr("Scale along %1. A non-uniform scale is why normals "
                                         "need mNormals, the inverse transpose of mModelView")
                                          .arg(axes[i]));
        connect(sc, &QDoubleSpinBox::valueChanged, this,
                [this, i](double v) { edit([&](Scene &s) { s.object.scale[i] = float(v); }); });
        m_scale[std::size_t(i)] = sc;
        scaleRow->addWidget(sc);
    }
    form->addRow(tr("Rotate"), rotationRow);
    form->addRow(tr("Scale"), scaleRow);

    m_autoRotate = new QCheckBox(tr("Auto-rotate about Y"), this);
    m_autoRotate->setToolTip(tr("Turns the model: a light in the object frame turns with it "
                                "(key Space)"));
    connect(m_autoRotate, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.object.autoRotate = on; }); });
    form->addRow(m_autoRotate);

    addResetButton(form, tr("Reset object"),
                   tr("The coarse unit sphere, untransformed, not rotating"),
                   [](Scene &s) { s.object = ObjectSettings{}; });
    refreshNow();
}

void ObjectPanel::refresh(const Scene &scene)
{
    const QSignalBlocker b1(m_shape), b2(m_tessellation), b3(m_autoRotate);
    m_shape->setCurrentIndex(int(scene.object.shape));
    m_tessellation->setValue(scene.object.tessellation);
    m_tessellation->setEnabled(scene.object.shape != Shape::Cube);
    m_autoRotate->setChecked(scene.object.autoRotate);
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker b4(m_rotation[std::size_t(i)]), b5(m_scale[std::size_t(i)]);
        m_rotation[std::size_t(i)]->setValue(double(scene.object.rotationDegrees[i]));
        m_scale[std::size_t(i)]->setValue(double(scene.object.scale[i]));
    }
}

} // namespace lb
