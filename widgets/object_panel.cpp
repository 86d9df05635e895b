#include "object_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>

namespace lb {

namespace {
constexpr int kShapeCount = 4; // the combo's entries after these name the mesh file
}

ObjectPanel::ObjectPanel(SceneDocument *document, QWidget *parent)
    : ScenePanel(document, ScenePart::Object, parent)
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    m_shape = makeCombo({tr("Cube (flat faces)"), tr("Sphere (smooth)"), tr("Torus"), tr("Plane")},
                        tr("The object: vPosition and vNormal come from this mesh. A built-in "
                           "shape replaces a mesh file"));
    connect(m_shape, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i < kShapeCount)
            edit([&](Scene &s) {
                s.object.shape = Shape(i);
                s.object.meshPath.clear();
            });
    });
    auto *open = new QPushButton(tr("Open..."), this);
    open->setToolTip(tr("Open a mesh file: any format Assimp reads (Ctrl+M; or drop a file on "
                        "the window)"));
    connect(open, &QPushButton::clicked, this, &ObjectPanel::openMeshRequested);
    auto *shapeRow = new QHBoxLayout;
    shapeRow->addWidget(m_shape, 1);
    shapeRow->addWidget(open);
    form->addRow(tr("Shape"), shapeRow);

    m_tessellation = new QSpinBox(this);
    m_tessellation->setRange(limits::kMinTessellation, limits::kMaxTessellation);
    m_tessellation->setKeyboardTracking(false);
    m_tessellation->setToolTip(tr("Subdivisions of the sphere, torus and plane. Few vertices "
                                  "show Gouraud's weakness: its highlight follows the vertices"));
    connect(m_tessellation, &QSpinBox::valueChanged, this,
            [this](int v) { edit([&](Scene &s) { s.object.tessellation = v; }); });
    form->addRow(tr("Tessellation"), m_tessellation);

    m_normals = makeCombo({tr("From the mesh"), tr("Smooth (crease angle)"), tr("Flat")},
                          tr("vNormal: the mesh's own normals (generated smooth when a file "
                             "has none), or generated: smooth, averaged over the triangles "
                             "around a vertex within the crease angle, or flat, one per "
                             "triangle"));
    connect(m_normals, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.object.normals = NormalMode(i); }); });
    form->addRow(tr("Normals"), m_normals);
    m_crease = makeSpin(0.0, double(limits::kMaxCreaseDegrees), 0, 5.0,
                        tr("Generated smooth normals average only triangles that meet at less "
                           "than this angle: 0 is flat, 180 smooths every edge"));
    m_crease->setSuffix(QStringLiteral("\u00b0"));
    connect(m_crease, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { edit([&](Scene &s) { s.object.creaseDegrees = float(v); }); });
    form->addRow(tr("Crease angle"), m_crease);
    m_showNormals = new QCheckBox(tr("Show normals as lines"), this);
    m_showNormals->setToolTip(tr("A short line along each vertex normal, transformed by "
                                 "mNormals as the shaders do (key N)"));
    connect(m_showNormals, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.object.showNormals = on; }); });
    form->addRow(m_showNormals);
    m_cullBackFaces = new QCheckBox(tr("Cull back faces (closed meshes)"), this);
    m_cullBackFaces->setToolTip(tr("Triangles facing away from the camera are not drawn: the "
                                   "same picture for a closed mesh, about twice as fast; an "
                                   "open mesh shows holes where its inside was"));
    connect(m_cullBackFaces, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.object.cullBackFaces = on; }); });
    form->addRow(m_cullBackFaces);
    m_adoptMaterial = new QCheckBox(tr("Use the mesh file's material"), this);
    m_adoptMaterial->setToolTip(tr("The mesh file's ambient, diffuse and specular colours "
                                   "and shininess replace Ka, Kd, Ks and shininess: now, and "
                                   "whenever a file is loaded"));
    connect(m_adoptMaterial, &QCheckBox::toggled, this,
            [this](bool on) { emit adoptFileMaterialRequested(on); });
    form->addRow(m_adoptMaterial);

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
    const ObjectSettings &o = scene.object;
    const QSignalBlocker b1(m_shape), b2(m_tessellation), b3(m_autoRotate), b6(m_normals),
        b7(m_crease), b8(m_showNormals), b9(m_adoptMaterial), b10(m_cullBackFaces);
    while (m_shape->count() > kShapeCount)
        m_shape->removeItem(kShapeCount);
    if (o.meshPath.isEmpty()) {
        m_shape->setCurrentIndex(int(o.shape));
    } else {
        m_shape->addItem(tr("File: %1").arg(QFileInfo(o.meshPath).fileName()));
        m_shape->setItemData(kShapeCount, o.meshPath, Qt::ToolTipRole);
        m_shape->setCurrentIndex(kShapeCount);
    }
    m_tessellation->setValue(o.tessellation);
    m_tessellation->setEnabled(o.meshPath.isEmpty() && o.shape != Shape::Cube);
    m_autoRotate->setChecked(o.autoRotate);
    m_normals->setCurrentIndex(int(o.normals));
    m_crease->setValue(double(o.creaseDegrees));
    m_crease->setEnabled(o.normals != NormalMode::Flat);
    m_showNormals->setChecked(o.showNormals);
    m_cullBackFaces->setChecked(o.cullBackFaces);
    m_adoptMaterial->setChecked(o.adoptFileMaterial);
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker b4(m_rotation[std::size_t(i)]), b5(m_scale[std::size_t(i)]);
        m_rotation[std::size_t(i)]->setValue(double(scene.object.rotationDegrees[i]));
        m_scale[std::size_t(i)]->setValue(double(scene.object.scale[i]));
    }
}

} // namespace lb
