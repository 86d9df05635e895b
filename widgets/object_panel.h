#pragma once
// Object: the scene's objects as a list (add, duplicate, remove, rename, show or hide, select),
// and the selected one's shape or mesh file and its tessellation, normals (the file's, smooth
// within a crease angle, or flat; shown as lines), texture (texture_controls.h), rotation,
// (possibly non-uniform) scale and translation per axis, and auto-rotate.

#include "scene_panel.h"

#include <functional>

#include <array>
#include <utility>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace lb {

class IntegerBox;
class TextureControls;

class ObjectPanel : public ScenePanel
{
    Q_OBJECT
public:
    explicit ObjectPanel(SceneDocument *document, QWidget *parent = nullptr);

    QListWidget *objectList() const { return m_list; }
    QPushButton *addButton() const { return m_add; }
    QPushButton *duplicateButton() const { return m_duplicate; }
    QPushButton *removeButton() const { return m_remove; }
    QComboBox *shapeCombo() const { return m_shape; }
    QSpinBox *tessellationBox() const { return m_tessellation; }
    QDoubleSpinBox *rotation(int i) const { return m_rotation[std::size_t(i)]; }
    QDoubleSpinBox *scale(int i) const { return m_scale[std::size_t(i)]; }
    QDoubleSpinBox *translation(int i) const { return m_translation[std::size_t(i)]; }
    TextureControls *texture() const { return m_texture; }
    QCheckBox *autoRotateCheck() const { return m_autoRotate; }
    QComboBox *normalsCombo() const { return m_normals; }
    QComboBox *facesCombo() const { return m_faces; }
    QDoubleSpinBox *creaseBox() const { return m_crease; }
    QCheckBox *showNormalsCheck() const { return m_showNormals; }
    QCheckBox *cullBackFacesCheck() const { return m_cullBackFaces; }
    QCheckBox *adoptMaterialCheck() const { return m_adoptMaterial; }
    // Where the panel learns why the selected object's mesh file is not drawn and why its
    // image is not shown (the object loader's meshProblem() and textureProblem());
    // refreshProblems() shows them again after a load.
    void setProblemLookups(std::function<QString()> mesh, std::function<QString()> texture);
    // The most the tessellation box takes for object `index` of `scene`, and why no more
    // (the scene budget: the memory all objects' meshes may take); none: kMaxTessellation.
    using TessellationLimit = std::function<std::pair<int, QString>(const Scene &, int index)>;
    void setTessellationLimit(TessellationLimit limit) { m_tessellationLimit = std::move(limit); }
    void refreshProblems();

signals:
    void openMeshRequested();  // the "Open..." button: the window shows its file dialog
    void openImageRequested(); // the texture's "Image..." button: likewise
    // "Use the mesh file's material": the object loader switches it and, with a file on
    // screen, takes its material in the same edit (ObjectLoader::setAdoptFileMaterial).
    void adoptFileMaterialRequested(bool on);

protected:
    void refresh(const Scene &scene) override;

private:
    void refreshList(const Scene &scene);

    std::function<QString()> m_meshProblem;
    TessellationLimit m_tessellationLimit;

    QListWidget *m_list;
    QPushButton *m_add, *m_duplicate, *m_remove;
    QComboBox *m_shape;
    IntegerBox *m_tessellation;
    std::array<QDoubleSpinBox *, 3> m_rotation{};
    std::array<QDoubleSpinBox *, 3> m_scale{};
    std::array<QDoubleSpinBox *, 3> m_translation{};
    TextureControls *m_texture;
    QCheckBox *m_autoRotate;
    QComboBox *m_normals;
    QComboBox *m_faces;
    QDoubleSpinBox *m_crease;
    QCheckBox *m_showNormals;
    QCheckBox *m_cullBackFaces;
    QCheckBox *m_adoptMaterial;
};

} // namespace lb
