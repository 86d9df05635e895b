#pragma once
// A mesh file as the import helper read it: the mesh (centred, scaled to fit the view, all
// node transforms applied), what else the file had (material, diffuse texture) and figures
// about the load. The workbench never touches the file with Assimp itself; see wire.h.

#include "lighting.h"
#include "mesh.h"
#include "texture.h"

#include <QString>
#include <QStringList>

#include <glm/vec3.hpp>

#include <functional>
#include <memory>
#include <optional>

namespace lb {

// The file's material, as far as it has one.
struct FileMaterial
{
    std::optional<glm::vec3> ka, kd, ks;
    std::optional<float> shininess;
    bool empty() const { return !ka && !kd && !ks && !shininess; }
};

// `current` with whatever the file has, brought into the panels' ranges.
Material adoptMaterial(const Material &current, const FileMaterial &file);

struct MeshFile
{
    QString path;
    std::shared_ptr<const Mesh> mesh; // normals only when the file has usable ones
    FileMaterial material;
    std::shared_ptr<const Texture> texture; // the diffuse texture, when it could be read
    QString textureProblem;                 // why a texture the file names is not used
    int meshes = 0;                         // mesh instances merged into `mesh`
    qint64 skippedFaces = 0;                // points, lines and faces with bad indices
    qint64 nonFiniteVertices = 0;           // NaN or infinite positions: dropped, with...
    qint64 droppedTriangles = 0;            // ...the triangles using them
    qint64 nonFiniteNormals = 0;            // NaN or infinite normals: the file's normals not used
    QStringList sideFileProblems;           // files the mesh names that were not used, and why
    double readSeconds = 0;                 // the file's reading, inside the helper
    QString reader;          // who read it: "assimp", or "ply" / "stl" (fast_mesh_readers.h)
    double seconds = 0;      // the whole load as the workbench saw it
    qint64 helperPeakKB = 0; // the helper's peak resident memory

    bool hasNormals() const { return mesh && !mesh->normals.empty(); }
    // Short remarks for the status bar: what was skipped or could not be used.
    QStringList remarks() const;
};

// What is drawn, for the status bar: "teapot.obj: 1,202 vertices, 2,256 triangles, loaded in
// 0.12 s, normals generated (remarks)". `loaded`: the file drawn, or nullptr for the shape
// called `name`; the counts as the window's locale writes them. `turned`: what the Faces
// choice turned (buildObjectMesh's remark), the first remark.
// `count` writes the counts (the window's: writtenCount() of app/common/language.h); none:
// QLocale()'s way.
QString meshSummary(const QString &name, qulonglong vertices, qulonglong triangles,
                    const MeshFile *loaded, const QString &turned = {},
                    const std::function<QString(qulonglong)> &count = {});

} // namespace lb
