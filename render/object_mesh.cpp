#include "object_mesh.h"

#include "mesh_normals.h"

namespace lb {

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
    key.creaseDegrees = object.normals == NormalMode::Flat ? 0.0f : object.creaseDegrees;
    return key;
}

std::shared_ptr<const Mesh> buildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                            const std::atomic_bool *cancel)
{
    std::shared_ptr<const Mesh> base =
        file ? file->mesh
             : std::make_shared<const Mesh>(makeShape(object.shape, object.tessellation));
    if (object.normals == NormalMode::File && !base->normals.empty())
        return base;
    const float crease = object.normals == NormalMode::Flat ? 0.0f : object.creaseDegrees;
    std::optional<Mesh> generated = withGeneratedNormals(*base, crease, cancel);
    if (!generated)
        return nullptr;
    return std::make_shared<const Mesh>(std::move(*generated));
}

} // namespace lb
