#pragma once
// The mesh the object panel asks for: a built-in shape or a loaded mesh file, with the normals
// the "Normals" choice asks for. Built on the caller's thread: the window calls it on a worker
// thread, the command line and the tests directly.

#include "mesh.h"
#include "mesh_file.h"
#include "scene.h"

#include <QByteArray>

#include <atomic>
#include <memory>
#include <new>

namespace lb {

// What the drawn mesh depends on; when it changes, the mesh is rebuilt.
struct ObjectMeshKey
{
    Shape shape = Shape::Sphere;
    int tessellation = 0;
    QString meshPath; // the file drawn; empty for the shape
    NormalMode normals = NormalMode::File;
    Faces faces = Faces::Outward;
    float creaseDegrees = 0.0f;
    bool operator==(const ObjectMeshKey &o) const;
    bool operator!=(const ObjectMeshKey &o) const { return !(*this == o); }
};

// `file` is the loaded mesh file, or nullptr to draw the shape.
ObjectMeshKey objectMeshKey(const ObjectSettings &object, const MeshFile *file);

// The work buildObjectMesh does, in triangles whose normals it generates: 0 when the file's
// own normals are drawn (the mesh is used as it is). Normal generation takes linear time for
// any mesh, crowded positions included (0.1-0.5 us a triangle measured here: 100,000
// triangles around one position in 10-50 ms), so this is what decides where a mesh is built.
std::size_t objectMeshWork(const ObjectSettings &object, const MeshFile *file);

// What buildObjectMesh throws when an allocation fails: a std::bad_alloc (whoever catches
// those catches it) that names the mesh: "out of memory building the torus at tessellation
// 2000". What it made so far is freed as it unwinds.
class ObjectMeshOutOfMemory : public std::bad_alloc
{
public:
    explicit ObjectMeshOutOfMemory(QByteArray what) : m_what(std::move(what)) {}
    const char *what() const noexcept override { return m_what.constData(); }

private:
    QByteArray m_what;
};

// Returns nullptr only when `cancel` was set; throws ObjectMeshOutOfMemory when memory runs out.
// `remark`, when given, is set to what the Faces choice turned ("faces turned: the file winds
// them clockwise"; mesh_orientation.h), or cleared.
std::shared_ptr<const Mesh> buildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                            const std::atomic_bool *cancel = nullptr,
                                            QString *remark = nullptr);

// The same for worker threads, where nothing may escape (Qt's thread pool aborts the process
// on an exception): `error` says why there is no mesh ("out of memory building ...").
struct ObjectMeshBuild
{
    std::shared_ptr<const Mesh> mesh; // nullptr: cancelled, or `error`
    QString error;
    QString remark; // what the Faces choice turned, as buildObjectMesh says
};
ObjectMeshBuild tryBuildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                   const std::atomic_bool *cancel = nullptr) noexcept;

} // namespace lb
