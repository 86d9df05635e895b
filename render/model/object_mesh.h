#pragma once
// The mesh the object panel asks for: a built-in shape or a loaded mesh file, with the normals
// the "Normals" choice asks for. Built on the caller's thread: the window calls it on a worker
// thread, the command line and the tests directly.

#include "mesh.h"
#include "mesh_file.h"
#include "scene.h"

#include <atomic>
#include <memory>

namespace lb {

// What the drawn mesh depends on; when it changes, the mesh is rebuilt.
struct ObjectMeshKey
{
    Shape shape = Shape::Sphere;
    int tessellation = 0;
    QString meshPath; // the file drawn; empty for the shape
    NormalMode normals = NormalMode::File;
    float creaseDegrees = 0.0f;
    bool operator==(const ObjectMeshKey &o) const;
    bool operator!=(const ObjectMeshKey &o) const { return !(*this == o); }
};

// `file` is the loaded mesh file, or nullptr to draw the shape.
ObjectMeshKey objectMeshKey(const ObjectSettings &object, const MeshFile *file);

// Returns nullptr only when `cancel` was set.
std::shared_ptr<const Mesh> buildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                            const std::atomic_bool *cancel = nullptr);

} // namespace lb
