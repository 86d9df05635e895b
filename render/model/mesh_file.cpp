#include "mesh_file.h"

#include "scene.h"

#include <glm/common.hpp>

#include <algorithm>

namespace lb {

Material adoptMaterial(const Material &current, const FileMaterial &file)
{
    Material m = current;
    auto colour = [](const glm::vec3 &c) { return glm::clamp(c, 0.0f, 1.0f); };
    if (file.ka)
        m.ka = colour(*file.ka);
    if (file.kd)
        m.kd = colour(*file.kd);
    if (file.ks)
        m.ks = colour(*file.ks);
    if (file.shininess)
        m.shininess = std::clamp(*file.shininess, limits::kMinShininess, limits::kMaxShininess);
    return m;
}

QStringList MeshFile::remarks() const
{
    QStringList r;
    if (skippedFaces > 0)
        r << QString("%1 points, lines or broken faces skipped").arg(skippedFaces);
    if (nonFiniteVertices > 0)
        r << QString("%1 vertices with non-finite coordinates dropped, with the %2 triangles "
                     "using them")
                 .arg(nonFiniteVertices)
                 .arg(droppedTriangles);
    if (nonFiniteNormals > 0)
        r << QString("%1 normals with non-finite coordinates: the file's normals not used")
                 .arg(nonFiniteNormals);
    r << sideFileProblems;
    if (!textureProblem.isEmpty())
        r << textureProblem;
    return r;
}

} // namespace lb
