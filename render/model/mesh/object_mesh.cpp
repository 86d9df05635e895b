#include "object_mesh.h"

#include "mesh_normals.h"
#include "mesh_orientation.h"
#include "mesh_weld.h"
#include "message_text.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <exception>

namespace lb {

namespace {
// Flat normals are smooth ones that stop at every edge.
float creaseOf(const ObjectSettings &object)
{
    return object.normals == NormalMode::Flat ? 0.0f : object.creaseDegrees;
}

// The translation context of this file's messages.
struct ObjectMeshMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::ObjectMesh)
};

// "out of memory building the torus at tessellation 2000", "... teapot.obj's normals (12288
// triangles)": whole sentences, one for each shape.
QString outOfMemory(const ObjectSettings &object, const MeshFile *file)
{
    const QString tessellation = QString::number(object.tessellation);
    if (file)
        return ObjectMeshMessages::tr("out of memory building %1's normals (%2 triangles)")
            .arg(escapedName(QFileInfo(file->path).fileName()),
                 QString::number(file->mesh ? qulonglong(file->mesh->triangleCount()) : 0));
    switch (object.shape) {
    case Shape::Cube:
        return ObjectMeshMessages::tr("out of memory building the cube");
    case Shape::Sphere:
        return ObjectMeshMessages::tr("out of memory building the sphere at tessellation %1")
            .arg(tessellation);
    case Shape::Torus:
        return ObjectMeshMessages::tr("out of memory building the torus at tessellation %1")
            .arg(tessellation);
    case Shape::Plane:
        return ObjectMeshMessages::tr("out of memory building the plane at tessellation %1")
            .arg(tessellation);
    }
    return ObjectMeshMessages::tr("out of memory building a mesh");
}
} // namespace

bool ObjectMeshKey::operator==(const ObjectMeshKey &o) const
{
    return shape == o.shape && tessellation == o.tessellation && meshPath == o.meshPath &&
           normals == o.normals && faces == o.faces && creaseDegrees == o.creaseDegrees;
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
    // A shape is outward already: outward and as-is draw it the same.
    key.faces = !file && object.faces == Faces::Outward ? Faces::File : object.faces;
    key.creaseDegrees = creaseOf(object);
    return key;
}

std::size_t objectMeshWork(const ObjectSettings &object, const MeshFile *file)
{
    if (!file)
        return shapeTriangleCount(object.shape, object.tessellation);
    if (object.normals == NormalMode::File && !file->mesh->normals.empty() &&
        object.faces == Faces::File)
        return 0;
    return file->mesh->triangleCount();
}

std::shared_ptr<const Mesh> buildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                            const std::atomic_bool *cancel, QString *remark)
{
    if (remark)
        remark->clear();
    try {
        std::shared_ptr<const Mesh> base =
            file ? file->mesh
                 : std::make_shared<const Mesh>(makeShape(object.shape, object.tessellation));
        const bool fileNormals = object.normals == NormalMode::File && !base->normals.empty();
        std::vector<std::uint32_t> weld;
        // Which way the faces look first: generated normals follow the winding.
        if (object.faces == Faces::Flipped) {
            base = std::make_shared<const Mesh>(flippedMesh(*base));
        } else if (object.faces == Faces::Outward && file) { // the shapes are outward
            // Welded once for the check and the normals (turning changes no position).
            weld = weldPositions(base->positions);
            std::optional<OrientationCheck> check = checkOrientation(*base, cancel, &weld);
            if (!check)
                return nullptr;
            if (!fileNormals) { // the file's normals are not drawn: nothing to say of them
                check->turnedNormals = 0;
                for (std::uint8_t &p : check->part)
                    p &= ~OrientationCheck::kTurnNormals;
            }
            if (check->changes()) {
                base = std::make_shared<const Mesh>(orientedMesh(*base, *check));
                if (remark)
                    *remark = orientationRemark(*check);
            }
        }
        if (!fileNormals) {
            std::optional<Mesh> generated = withGeneratedNormals(*base, creaseOf(object), cancel,
                                                                 weld.empty() ? nullptr : &weld);
            if (!generated)
                return nullptr;
            std::vector<std::uint32_t>().swap(weld);
            base = std::make_shared<const Mesh>(std::move(*generated));
        }
        if (object.faces == Faces::TwoSided)
            base = std::make_shared<const Mesh>(twoSidedMesh(*base));
        return base;
    } catch (const ObjectMeshOutOfMemory &) {
        throw;
    } catch (const std::bad_alloc &) {
        // What was made is freed by now: there is room for the message.
        throw ObjectMeshOutOfMemory(outOfMemory(object, file).toUtf8());
    } catch (const std::length_error &) { // a vector longer than it may be: the same to the user
        throw ObjectMeshOutOfMemory(outOfMemory(object, file).toUtf8());
    }
}

ObjectMeshBuild tryBuildObjectMesh(const ObjectSettings &object, const MeshFile *file,
                                   const std::atomic_bool *cancel) noexcept
{
    try {
        ObjectMeshBuild b;
        b.mesh = buildObjectMesh(object, file, cancel, &b.remark);
        return b;
    } catch (const std::exception &e) {
        try {
            return {nullptr, QString::fromUtf8(e.what()), {}};
        } catch (...) { // not even the message fits: a shorter one below
        }
    } catch (...) {
    }
    try {
        return {nullptr, ObjectMeshMessages::tr("out of memory building a mesh"), {}};
    } catch (...) { // not even that fits: the QString is made of a literal (no allocation)
    }
    return {nullptr, QStringLiteral("out of memory building a mesh"), {}};
}

} // namespace lb
