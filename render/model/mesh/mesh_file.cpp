#include "mesh_file.h"

#include "scene.h"

#include <QCoreApplication>
#include <QLocale>

#include <glm/common.hpp>

#include <algorithm>

namespace lb {

namespace {
// The translation context of this file's messages.
struct MeshFileMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::MeshFile)
};
} // namespace

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
        r << MeshFileMessages::tr("%1 points, lines or broken faces skipped").arg(skippedFaces);
    if (nonFiniteVertices > 0)
        r << MeshFileMessages::tr(
                 "%1 vertices with non-finite coordinates dropped, with the %2 triangles "
                 "using them")
                 .arg(nonFiniteVertices)
                 .arg(droppedTriangles);
    if (nonFiniteNormals > 0)
        r << MeshFileMessages::tr(
                 "%1 normals with non-finite coordinates: the file's normals not used")
                 .arg(nonFiniteNormals);
    r << sideFileProblems;
    if (!textureProblem.isEmpty())
        r << textureProblem;
    return r;
}

QString meshSummary(const QString &name, qulonglong vertices, qulonglong triangles,
                    const MeshFile *loaded, const QString &turned,
                    const std::function<QString(qulonglong)> &count)
{
    const QLocale locale;
    const auto written = [&](qulonglong n) { return count ? count(n) : locale.toString(n); };
    const QString v = written(vertices), t = written(triangles);
    if (!loaded)
        return MeshFileMessages::tr("%1: %2 vertices, %3 triangles").arg(name, v, t);
    const QString seconds = QString::number(loaded->seconds, 'f', 2);
    QString s;
    if (loaded->hasNormals())
        s = MeshFileMessages::tr("%1: %2 vertices, %3 triangles, loaded in %4 s")
                .arg(name, v, t, seconds);
    else if (loaded->nonFiniteNormals > 0) // a remark says why
        s = MeshFileMessages::tr("%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated")
                .arg(name, v, t, seconds);
    else
        s = MeshFileMessages::tr(
                "%1: %2 vertices, %3 triangles, loaded in %4 s, normals generated (the "
                "file has none)")
                .arg(name, v, t, seconds);
    QStringList remarks = loaded->remarks();
    if (!turned.isEmpty())
        remarks.prepend(turned);
    if (!remarks.isEmpty())
        //: a mesh's summary (%1) and what was skipped or not used in its file (%2, a list)
        s = MeshFileMessages::tr("%1 (%2)").arg(s, remarks.join("; "));
    return s;
}

} // namespace lb
