#include "object_panel.h"

#include "narrow_forms.h"
#include "number_box.h"
#include "texture_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QListWidget>
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

    // The list: a tick shows or hides an object, a double click (or F2) renames it.
    m_list = new QListWidget(this);
    m_list->setToolTip(tr("The scene's objects, each with its own mesh, transform and material: "
                          "select one to edit it here and in the Material panel (or click it "
                          "in the view). Untick to hide; double-click to rename"));
    m_list->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    // Five rows, fixed: a list that may grow makes the panel take all the dock's height and
    // spreads the rest of the form apart.
    m_list->setFixedHeight(m_list->fontMetrics().height() * 5 + 8);
    m_list->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0)
            edit([&](Scene &s) {
                if (row < int(s.objects.size()))
                    s.selected = row;
            });
    });
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem *item) {
        const int row = m_list->row(item);
        const bool visible = item->checkState() == Qt::Checked;
        const QString name = item->text().trimmed();
        edit([&](Scene &s) {
            if (row < 0 || row >= int(s.objects.size()))
                return;
            ObjectSettings &o = s.objects[std::size_t(row)];
            o.visible = visible;
            // The shown name typed again keeps following the shape (or the file's languages); a
            // new one is the user's, in the language typed.
            if (name != displayName(o))
                o.name = plainText(name);
        });
        refreshNow(); // an emptied name shows the shape's or file's again
    });
    form->addRow(m_list);
    m_add = new QPushButton(tr("Add"), this);
    m_add->setToolTip(tr("A new sphere in the first free place near the centre (at most %1 "
                         "objects; R frames them all)")
                          .arg(kMaxObjects));
    connect(m_add, &QPushButton::clicked, this, [this] {
        edit([](Scene &s) {
            ObjectSettings added;
            added.translation = freePlace(s);
            addObject(s, added);
        });
    });
    m_duplicate = new QPushButton(tr("Duplicate"), this);
    m_duplicate->setToolTip(tr("A copy of the selected object, material and all, in the first free "
                               "place near the centre"));
    connect(m_duplicate, &QPushButton::clicked, this, [this] {
        edit([&](Scene &s) {
            ObjectSettings copy = s.selectedObject();
            copy.translation = freePlace(s);
            // The copy's name is the user's to edit, saved as shown: in the user's language.
            if (!copy.name.isEmpty())
                //: the name of a duplicated object; %1 the original's name
                copy.name = plainText(tr("%1 copy").arg(displayName(copy)));
            addObject(s, copy);
        });
    });
    m_remove = new QPushButton(tr("Remove"), this);
    m_remove->setToolTip(tr("Removes the selected object (the last one stays); lights in its "
                            "frame go to the object before it"));
    connect(m_remove, &QPushButton::clicked, this,
            [this] { edit([](Scene &s) { removeObject(s, s.selected); }); });
    auto *listButtons = new WrapRow(WrapRow::Room::Left);
    listButtons->addWidget(m_add);
    listButtons->addWidget(m_duplicate);
    listButtons->addWidget(m_remove);
    form->addRow(listButtons);

    m_shape = makeCombo({tr("Cube (flat faces)"), tr("Sphere (smooth)"), tr("Torus"), tr("Plane")},
                        tr("The object: vPosition and vNormal come from this mesh. A built-in "
                           "shape replaces a mesh file"));
    connect(m_shape, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i < kShapeCount)
            edit([&](Scene &s) {
                s.selectedObject().shape = Shape(i);
                s.selectedObject().meshPath.clear();
            });
    });
    auto *open = new QPushButton(tr("Open..."), this);
    open->setToolTip(tr("Open a mesh file: any format Assimp reads (Ctrl+M; or drop a file on "
                        "the window)"));
    connect(open, &QPushButton::clicked, this, &ObjectPanel::openMeshRequested);
    auto *shapeRow = new WrapRow(WrapRow::Room::Left);
    m_shape->setSizePolicy(QSizePolicy::Expanding, m_shape->sizePolicy().verticalPolicy());
    shapeRow->addWidget(m_shape);
    shapeRow->addWidget(open);
    form->addRow(tr("Shape"), shapeRow);

    m_tessellation = new IntegerBox(this);
    m_tessellation->setRange(limits::kMinTessellation, limits::kMaxTessellation);
    m_tessellation->setToolTip(tr("Subdivisions of the sphere, torus and plane. Few vertices "
                                  "show Gouraud's weakness: its highlight follows the vertices"));
    connect(m_tessellation, &QSpinBox::valueChanged, this,
            [this](int v) { edit([&](Scene &s) { s.selectedObject().tessellation = v; }); });
    form->addRow(tr("Tessellation"), m_tessellation);

    m_normals = makeCombo({tr("From the mesh"), tr("Smooth (crease angle)"), tr("Flat")},
                          tr("vNormal: the mesh's own normals (generated smooth when a file "
                             "has none), or generated: smooth, averaged over the triangles "
                             "around a vertex within the crease angle, or flat, one per "
                             "triangle"));
    connect(m_normals, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.selectedObject().normals = NormalMode(i); }); });
    form->addRow(tr("Normals"), m_normals);
    m_faces = makeCombo({tr("Outward"), tr("As in the file"), tr("Flipped"), tr("Both sides lit")},
                        tr("Which way a mesh file's faces look. Outward: a closed part wound "
                           "inwards (lit from inside) is turned, with its normals, and the "
                           "status line says so; as in the file; every face flipped; or both "
                           "sides lit, each with the normal facing the camera (for open "
                           "meshes: a sheet, a scan with holes)"));
    connect(m_faces, &QComboBox::currentIndexChanged, this,
            [this](int i) { edit([&](Scene &s) { s.selectedObject().faces = Faces(i); }); });
    form->addRow(tr("Faces"), m_faces);
    m_crease = makeSpin(0.0, double(limits::kMaxCreaseDegrees), 0, 5.0,
                        tr("Generated smooth normals average only triangles that meet at less "
                           "than this angle: 0 is flat, 180 smooths every edge"));
    m_crease->setSuffix(QStringLiteral("\u00b0"));
    connect(m_crease, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit([&](Scene &s) { s.selectedObject().creaseDegrees = float(v); });
    });
    form->addRow(tr("Crease angle"), m_crease);
    m_showNormals = new WrapCheckBox(tr("Show normals as lines"), this);
    m_showNormals->setToolTip(tr("A short line along each vertex normal, transformed by "
                                 "mNormals as the shaders do (key N)"));
    connect(m_showNormals, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.selectedObject().showNormals = on; }); });
    form->addRow(m_showNormals);
    m_cullBackFaces = new WrapCheckBox(tr("Cull back faces (closed meshes)"), this);
    m_cullBackFaces->setToolTip(tr("Triangles facing away from the camera are not drawn: the "
                                   "same picture for a closed mesh, about twice as fast; an "
                                   "open mesh shows holes where its inside was"));
    connect(m_cullBackFaces, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.selectedObject().cullBackFaces = on; }); });
    form->addRow(m_cullBackFaces);
    m_texture = new TextureControls(document, this);
    connect(m_texture, &TextureControls::openImageRequested, this,
            &ObjectPanel::openImageRequested);
    form->addRow(m_texture);
    m_adoptMaterial = new WrapCheckBox(tr("Use the mesh file's material"), this);
    m_adoptMaterial->setToolTip(tr("The mesh file's ambient, diffuse and specular colours "
                                   "and shininess replace Ka, Kd, Ks and shininess: now, and "
                                   "whenever a file is loaded"));
    connect(m_adoptMaterial, &QCheckBox::toggled, this,
            [this](bool on) { emit adoptFileMaterialRequested(on); });
    form->addRow(m_adoptMaterial);

    const char *axes[3] = {"X", "Y", "Z"};
    auto *rotationRow = new WrapRow;
    auto *scaleRow = new WrapRow;
    auto *translationRow = new WrapRow;
    // One spin box per axis of a model transform vector of the selected object.
    const auto axisSpin = [this](WrapRow *row, glm::vec3 ObjectSettings::*member, int i, double lo,
                                 double hi, int decimals, double step, const QString &tip) {
        QDoubleSpinBox *spin = makeSpin(lo, hi, decimals, step, tip);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, member, i](double v) {
            edit([&](Scene &s) { (s.selectedObject().*member)[i] = float(v); });
        });
        row->addWidget(spin);
        return spin;
    };
    for (int i = 0; i < 3; ++i) {
        QDoubleSpinBox *r =
            axisSpin(rotationRow, &ObjectSettings::rotationDegrees, i, -360.0, 360.0, 1, 5.0,
                     tr("Rotation about %1 in degrees (model matrix; applied X, "
                        "then Y, then Z)")
                         .arg(axes[i]));
        r->setWrapping(true);
        m_rotation[std::size_t(i)] = r;
        m_scale[std::size_t(i)] = axisSpin(
            scaleRow, &ObjectSettings::scale, i, limits::kMinScale, limits::kMaxScale, 2, 0.1,
            tr("Scale along %1. A non-uniform scale is why normals need mNormals, the "
               "inverse transpose of mModelView")
                .arg(axes[i]));
        m_translation[std::size_t(i)] =
            axisSpin(translationRow, &ObjectSettings::translation, i, -limits::kMaxCoordinate,
                     limits::kMaxCoordinate, 2, 0.25,
                     tr("Translation along world %1: where the object's centre lies (model matrix, "
                        "applied last)")
                         .arg(axes[i]));
    }
    //: the row of the object's rotation about X, Y and Z
    form->addRow(tr("Rotate"), rotationRow);
    //: the row of the object's scale along X, Y and Z
    form->addRow(tr("Scale"), scaleRow);
    //: the row of the object's translation along X, Y and Z
    form->addRow(tr("Move"), translationRow);

    m_autoRotate = new WrapCheckBox(tr("Auto-rotate about Y"), this);
    m_autoRotate->setToolTip(tr("Turns the model: a light in the object frame turns with it "
                                "(key Space)"));
    connect(m_autoRotate, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.selectedObject().autoRotate = on; }); });
    form->addRow(m_autoRotate);

    addResetButton(form, tr("Reset object"),
                   tr("The selected object back to the coarse unit sphere, unrotated, unscaled "
                      "and not turning; its name, place and material stay"),
                   [](Scene &s) {
                       ObjectSettings &o = s.selectedObject();
                       ObjectSettings reset;
                       reset.name = o.name;
                       reset.translation = o.translation;
                       reset.material = o.material;
                       o = reset;
                   });
    refreshNow();
}

void ObjectPanel::refreshList(const Scene &scene)
{
    const QSignalBlocker block(m_list);
    const int n = int(scene.objects.size());
    while (m_list->count() > n)
        delete m_list->takeItem(m_list->count() - 1);
    while (m_list->count() < n) {
        auto *item = new QListWidgetItem(m_list);
        item->setFlags(item->flags() | Qt::ItemIsEditable | Qt::ItemIsUserCheckable);
    }
    for (int i = 0; i < n; ++i) {
        const ObjectSettings &o = scene.objects[std::size_t(i)];
        QListWidgetItem *item = m_list->item(i);
        item->setText(displayName(o));
        item->setCheckState(o.visible ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(o.meshPath.isEmpty() ? displayName(o) : o.meshPath);
    }
    m_list->setCurrentRow(scene.selected);
    m_add->setEnabled(n < kMaxObjects);
    m_duplicate->setEnabled(n < kMaxObjects);
    m_remove->setEnabled(n > 1);
}

void ObjectPanel::setProblemLookups(std::function<QString()> mesh, std::function<QString()> texture)
{
    m_meshProblem = std::move(mesh);
    m_texture->setProblemLookup(std::move(texture));
    refreshProblems();
}

void ObjectPanel::refreshProblems()
{
    refreshNow();
    m_texture->refreshProblem();
}

void ObjectPanel::refresh(const Scene &scene)
{
    refreshList(scene);
    const ObjectSettings &o = scene.selectedObject();
    const QSignalBlocker b1(m_shape), b2(m_tessellation), b3(m_autoRotate), b6(m_normals),
        b7(m_crease), b11(m_faces), b8(m_showNormals), b9(m_adoptMaterial), b10(m_cullBackFaces);
    while (m_shape->count() > kShapeCount)
        m_shape->removeItem(kShapeCount);
    if (o.meshPath.isEmpty()) {
        m_shape->setCurrentIndex(int(o.shape));
    } else {
        // A file the scene names that could not be read: still named (a save keeps it), its
        // shape drawn meanwhile.
        const QString problem = m_meshProblem ? m_meshProblem() : QString();
        const QString name = QFileInfo(o.meshPath).fileName();
        //: the shape combo's entry for a mesh file; %1 the file's name
        m_shape->addItem(problem.isEmpty() ? tr("File: %1").arg(name)
                                           : tr("File: %1 (not loaded)").arg(name));
        m_shape->setItemData(kShapeCount, problem.isEmpty() ? o.meshPath : problem,
                             Qt::ToolTipRole);
        m_shape->setCurrentIndex(kShapeCount);
    }
    // Set before the value: a lower maximum would clamp it. The box goes no higher than the
    // budget allows (the scene's own value stays shown if it is higher).
    const auto [most, why] = m_tessellationLimit ? m_tessellationLimit(scene, scene.selected)
                                                 : std::pair(limits::kMaxTessellation, QString());
    m_tessellation->setMaximum(std::max(most, o.tessellation));
    m_tessellation->setMaximumReason(most < limits::kMaxTessellation ? why : QString());
    m_tessellation->setValue(o.tessellation);
    m_tessellation->setEnabled(o.meshPath.isEmpty() && o.shape != Shape::Cube);
    m_autoRotate->setChecked(o.autoRotate);
    m_normals->setCurrentIndex(int(o.normals));
    m_faces->setCurrentIndex(int(o.faces));
    m_crease->setValue(double(o.creaseDegrees));
    m_crease->setEnabled(o.normals != NormalMode::Flat);
    m_showNormals->setChecked(o.showNormals);
    m_cullBackFaces->setChecked(o.cullBackFaces);
    m_adoptMaterial->setChecked(o.adoptFileMaterial);
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker b4(m_rotation[std::size_t(i)]), b5(m_scale[std::size_t(i)]),
            b12(m_translation[std::size_t(i)]);
        m_rotation[std::size_t(i)]->setValue(double(o.rotationDegrees[i]));
        m_scale[std::size_t(i)]->setValue(double(o.scale[i]));
        m_translation[std::size_t(i)]->setValue(double(o.translation[i]));
    }
}

} // namespace lb
