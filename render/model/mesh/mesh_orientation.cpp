#include "mesh_orientation.h"

#include "mesh_weld.h"
#include "parallel_for.h"

#include <QCoreApplication>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace lb {

namespace {

struct MeshOrientationMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::MeshOrientation)
};

// Disjoint sets of positions (path halving; the root is any member).
class Parts
{
public:
    explicit Parts(std::size_t n) : m_parent(n)
    {
        for (std::size_t i = 0; i < n; ++i)
            m_parent[i] = std::uint32_t(i);
    }
    std::uint32_t find(std::uint32_t v)
    {
        while (m_parent[v] != v) {
            m_parent[v] = m_parent[m_parent[v]];
            v = m_parent[v];
        }
        return v;
    }
    void join(std::uint32_t a, std::uint32_t b)
    {
        a = find(a), b = find(b);
        if (a != b)
            m_parent[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::uint32_t> m_parent;
};

// What a part's triangles add up to. With e = (b - a) x (c - a) per triangle: `net` is the
// sum of e (zero for a closed surface), `area` the sum of |e|, `volume` six times the signed
// volume about the origin (the sum of a . (b x c)), `centre` the area-weighted sum of the
// triangles' centres (three times), `normals` the sum of e . (na + nb + nc).
struct PartSums
{
    glm::dvec3 net{0.0}, centre{0.0};
    double area = 0.0, volume = 0.0, normals = 0.0;
};

constexpr double kMaxNetArea = 0.1; // of the area: holes this big still enclose a volume

Mesh copyOf(const Mesh &mesh, std::size_t copies)
{
    Mesh out;
    const std::size_t n = mesh.vertexCount();
    if (copies * n > std::size_t(0xffffffffu)) // 32-bit indices
        throw std::length_error("mesh too large to copy");
    auto repeat = [copies](auto &to, const auto &from) {
        to.reserve(from.size() * copies);
        for (std::size_t c = 0; c < copies; ++c)
            to.insert(to.end(), from.begin(), from.end());
    };
    repeat(out.positions, mesh.positions);
    repeat(out.normals, mesh.normals);
    repeat(out.colors, mesh.colors);
    repeat(out.uvs, mesh.uvs);
    return out;
}

} // namespace

std::optional<OrientationCheck> checkOrientation(const Mesh &mesh, const std::atomic_bool *cancel,
                                                 const std::vector<std::uint32_t> *givenWeld)
{
    auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    const std::size_t triangles = mesh.triangleCount();
    OrientationCheck check;
    if (triangles == 0)
        return check;
    std::vector<std::uint32_t> ownWeld;
    const std::vector<std::uint32_t> &weld = givenOrOwnWeld(mesh.positions, givenWeld, ownWeld);
    if (cancelled())
        return std::nullopt;
    const std::uint32_t *index = mesh.indices.data();
    Parts sets(mesh.vertexCount());
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t a = weld[index[3 * t]];
        sets.join(a, weld[index[3 * t + 1]]);
        sets.join(a, weld[index[3 * t + 2]]);
        if ((t & 0xffff) == 0 && cancelled())
            return std::nullopt;
    }
    // Each root's part, numbered in the order met.
    constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<std::uint32_t> partOf(mesh.vertexCount(), kNone);
    std::vector<std::uint32_t> triPart(triangles);
    std::uint32_t partCount = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t root = sets.find(weld[index[3 * t]]);
        if (partOf[root] == kNone)
            partOf[root] = partCount++;
        triPart[t] = partOf[root];
    }
    if (cancelled())
        return std::nullopt;
    // The sums, each slice of triangles into its own table of parts, added up after (a
    // triangle soup's many parts cost a table per slice: the slices are few).
    const bool normals = mesh.normals.size() == mesh.vertexCount();
    const std::size_t slices =
        triangles < 200'000 ? 1
                            : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    std::vector<std::vector<PartSums>> sliceSums(slices);
    parallelFor(triangles, slices, [&](std::size_t first, std::size_t last, std::size_t slice) {
        std::vector<PartSums> &sums = sliceSums[slice];
        sums.resize(partCount);
        for (std::size_t t = first; t < last; ++t) {
            PartSums &s = sums[triPart[t]];
            const glm::dvec3 a = mesh.positions[index[3 * t]], b = mesh.positions[index[3 * t + 1]],
                             c = mesh.positions[index[3 * t + 2]];
            const glm::dvec3 e = glm::cross(b - a, c - a);
            const double area = glm::length(e);
            if (!std::isfinite(area))
                continue;
            s.net += e;
            s.area += area;
            s.volume += glm::dot(a, glm::cross(b, c));
            s.centre += area * (a + b + c);
            if (normals)
                s.normals += glm::dot(e, glm::dvec3(mesh.normals[index[3 * t]] +
                                                    mesh.normals[index[3 * t + 1]] +
                                                    mesh.normals[index[3 * t + 2]]));
            if ((t & 0xffff) == 0 && cancelled())
                return;
        }
    });
    if (cancelled())
        return std::nullopt;
    std::vector<PartSums> sums = std::move(sliceSums[0]);
    for (std::size_t slice = 1; slice < slices; ++slice)
        for (std::size_t p = 0; p < partCount; ++p) {
            const PartSums &o = sliceSums[slice][p];
            sums[p].net += o.net;
            sums[p].centre += o.centre;
            sums[p].area += o.area;
            sums[p].volume += o.volume;
            sums[p].normals += o.normals;
        }
    check.parts = sums.size();
    std::vector<std::uint8_t> turn(sums.size(), 0);
    for (std::size_t p = 0; p < sums.size(); ++p) {
        const PartSums &s = sums[p];
        if (!(s.area > 0.0) || glm::length(s.net) > kMaxNetArea * s.area)
            continue;
        // The volume about the part's centre: what a hole adds is least from there.
        const glm::dvec3 centre = s.centre / (3.0 * s.area);
        const double volume = s.volume - glm::dot(centre, s.net);
        // A part with no volume to speak of (a flat closed sheet: both sides) says nothing.
        if (!(std::abs(volume) > 1e-6 * std::pow(s.area, 1.5)))
            continue;
        ++check.enclosing;
        const bool inwards = volume < 0.0;
        if (inwards) {
            turn[p] |= OrientationCheck::kTurnFaces;
            ++check.turnedFaces;
        }
        if (normals && (inwards ? -s.normals : s.normals) < 0.0) {
            turn[p] |= OrientationCheck::kTurnNormals;
            ++check.turnedNormals;
        }
    }
    if (check.changes()) {
        check.part.resize(triangles);
        for (std::size_t t = 0; t < triangles; ++t)
            check.part[t] = turn[triPart[t]];
    }
    return check;
}

Mesh orientedMesh(const Mesh &mesh, const OrientationCheck &check)
{
    Mesh out = mesh;
    const std::size_t triangles = out.triangleCount();
    if (check.part.size() != triangles)
        return out;
    std::vector<std::uint8_t> negate(out.normals.empty() ? 0 : out.vertexCount(), 0);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint8_t what = check.part[t];
        if (what & OrientationCheck::kTurnFaces)
            std::swap(out.indices[3 * t + 1], out.indices[3 * t + 2]);
        if ((what & OrientationCheck::kTurnNormals) && !negate.empty())
            for (int k = 0; k < 3; ++k)
                negate[out.indices[3 * t + k]] = 1;
    }
    for (std::size_t v = 0; v < negate.size(); ++v)
        if (negate[v])
            out.normals[v] = -out.normals[v];
    return out;
}

Mesh flippedMesh(const Mesh &mesh)
{
    Mesh out = mesh;
    for (std::size_t t = 0; t < out.triangleCount(); ++t)
        std::swap(out.indices[3 * t + 1], out.indices[3 * t + 2]);
    for (glm::vec3 &n : out.normals)
        n = -n;
    return out;
}

Mesh twoSidedMesh(const Mesh &mesh)
{
    Mesh out = copyOf(mesh, 2);
    const std::size_t n = mesh.vertexCount();
    for (std::size_t v = n; v < out.normals.size(); ++v)
        out.normals[v] = -out.normals[v];
    const std::size_t corners = mesh.triangleCount() * 3;
    out.indices.reserve(2 * corners);
    out.indices.assign(mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(corners));
    const std::uint32_t offset = std::uint32_t(n);
    for (std::size_t c = 0; c < corners; c += 3) {
        out.indices.push_back(mesh.indices[c] + offset);
        out.indices.push_back(mesh.indices[c + 2] + offset);
        out.indices.push_back(mesh.indices[c + 1] + offset);
    }
    return out;
}

QString orientationRemark(const OrientationCheck &check)
{
    QStringList r;
    const QString of = QString::number(check.enclosing);
    if (check.turnedFaces == check.enclosing && check.turnedFaces > 0)
        r << MeshOrientationMessages::tr("faces turned: the file winds them clockwise");
    else if (check.turnedFaces > 0)
        r << MeshOrientationMessages::tr(
                 "faces of %1 of %2 closed parts turned: the file winds them clockwise")
                 .arg(QString::number(check.turnedFaces), of);
    if (check.turnedNormals == check.enclosing && check.turnedNormals > 0)
        r << MeshOrientationMessages::tr("normals turned: the file's point inwards");
    else if (check.turnedNormals > 0)
        r << MeshOrientationMessages::tr(
                 "normals of %1 of %2 closed parts turned: the file's point inwards")
                 .arg(QString::number(check.turnedNormals), of);
    return r.join(QStringLiteral("; "));
}

} // namespace lb
