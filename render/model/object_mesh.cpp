#include "object_mesh.h"

#include "mesh_normals.h"

namespace lb {

namespace {
// Flat normals are smooth ones that stop at every edge.
float creaseOf(const ObjectSettings &object)
{
    return object.normals == NormalMode::Flat ? 0.0f : object.creaseDegrees;
}
} // namespace

bool ObjectMeshKey::operator==(const ObjectMeshKey &o) const
{
    return shape == o.shape && tessellation == o.tessellation && meshPath == o.meshPath &&
           normals == o.normals && creaseDegrees == o.creaseDegrees;
}

ObjectMeshKey objectMeshKey(const ObjectSettings &object, const MeshFile *file)
{
    ObjectMeshKey key;
    if (file) {
        key.meshPath = file->path;
    } else {
        key.shape = object.shape;
        key.tessellation = object.shape == Shape::Cube ? 0 : object.tessellation;
    }
    key.normals = object.normals;
    key.creaseDegrees = creaseOf(object);
    return key;
}

std::size_t objectMeshWork(const ObjectSettings &object, const MeshFile *file)
{
    if (!file)
        return shapeTriangleCount(object.shape, object.tessellation);
    if (object.normals == NormalMode::File && !file->mesh->normals.empty())
        return 0;
    return file->mesh->triangleCount();
}

std::shared_ptr<const Mesh> buildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                            const std::atomic_bool *cancel)
{
    std::shared_ptr<const Mesh> base =
        file ? file->mesh
             : std::make_shared<const Mesh>(makeShape(object.shape, object.tessellation));
    if (object.normals == NormalMode::File && !base->normals.empty())
        return base;
    std::optional<Mesh> generated = withGeneratedNormals(*base, creaseOf(object), cancel);
    if (!generated)
        return nullptr;
    return std::make_shared<const Mesh>(std::move(*generated));
}

} // namespace lb
