#include "mesh_normals.h"

#include "mesh_weld.h"
#include "parallel_for.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>
#include <unordered_map>

namespace lb {

namespace {

// acos within 7e-5 radians (Abramowitz and Stegun 4.4.45): a weight needs no more, and
// std::acos took a third of the time on big meshes.
float approximateAcos(float x)
{
    const float a = std::abs(x);
    const float r =
        std::sqrt(1.0f - a) * (1.5707288f + a * (-0.2121144f + a * (0.0742610f - 0.0187293f * a)));
    return x >= 0.0f ? r : 3.14159265f - r;
}

// The angle at `at` between the edges to `a` and `b`, given those edges and their lengths.
float cornerAngle(const glm::vec3 &toA, float lengthA, const glm::vec3 &toB, float lengthB)
{
    if (lengthA == 0.0f || lengthB == 0.0f)
        return 0.0f;
    return approximateAcos(std::clamp(glm::dot(toA, toB) / (lengthA * lengthB), -1.0f, 1.0f));
}

// How far a face's normal may lie from the mean of the faces around a position for the fast
// path below: half the crease, less a margin for float rounding (an error of 1e-7 in a dot
// product near 1 is 5e-4 radians of angle), so that any two faces within it of the mean are
// surely within the crease of each other as the exact comparison computes it.
float halfCreaseCosine(float creaseDegrees)
{
    const float half = 0.5f * glm::radians(std::clamp(creaseDegrees, 0.0f, 180.0f)) - 2e-3f;
    return half <= 0.0f ? 1.0f : std::cos(half);
}

// `v` made unit length, or +Z when it has none (the corners around it cancel out).
glm::vec3 unitOr(const glm::vec3 &v)
{
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Positions with more corners than this (a fan, a cone's apex, bad data all moved to the
// origin) are summed by bins of normals instead of corner by corner, which would take the
// square of the corners.
constexpr std::size_t kBinnedCorners = 64;
// The bins: a cube map of 32x32 cells a face, about 2.8 degrees across.
constexpr int kBinSide = 32;
constexpr int kBinCount = 6 * kBinSide * kBinSide;

int binOf(const glm::vec3 &n)
{
    const glm::vec3 a = glm::abs(n);
    int face;
    float u, v, major;
    if (a.x >= a.y && a.x >= a.z) {
        face = n.x > 0 ? 0 : 1;
        major = a.x, u = n.y, v = n.z;
    } else if (a.y >= a.z) {
        face = n.y > 0 ? 2 : 3;
        major = a.y, u = n.x, v = n.z;
    } else {
        face = n.z > 0 ? 4 : 5;
        major = a.z, u = n.x, v = n.y;
    }
    auto cell = [](float t) {
        return std::clamp(int((t + 1.0f) * 0.5f * kBinSide), 0, kBinSide - 1);
    };
    return (face * kBinSide + cell(u / major)) * kBinSide + cell(v / major);
}

// What a big position's corners sum, in linear time: the corners are binned by their
// triangle's normal; every bin takes the bins whose mean normal is within the crease of its
// own mean, and its corners share that sum. (Exact per corner for small positions; here a
// corner at the crease's edge may fall on the other side of it by a bin's width.)
struct Bins
{
    std::vector<int> slot = std::vector<int>(kBinCount, -1); // bin -> index in the lists
    std::vector<int> occupied;
    std::vector<glm::vec3> weighted, directions, sums;

    void sum(const std::uint32_t *begin, const std::uint32_t *end,
             const std::vector<glm::vec3> &faceNormal, const std::vector<float> &angle,
             float threshold, std::vector<glm::vec3> &cornerSum)
    {
        for (const int b : occupied)
            slot[b] = -1;
        occupied.clear();
        weighted.clear();
        directions.clear();
        cornerSum.assign(std::size_t(end - begin), glm::vec3(0.0f));
        std::vector<int> cornerSlot(std::size_t(end - begin), -1);
        for (const std::uint32_t *c = begin; c != end; ++c) {
            const glm::vec3 &n = faceNormal[*c / 3];
            if (n == glm::vec3(0.0f))
                continue;
            const int b = binOf(n);
            if (slot[b] < 0) {
                slot[b] = int(occupied.size());
                occupied.push_back(b);
                weighted.emplace_back(0.0f);
                directions.emplace_back(0.0f);
            }
            weighted[std::size_t(slot[b])] += angle[*c] * n;
            directions[std::size_t(slot[b])] += n;
            cornerSlot[std::size_t(c - begin)] = slot[b];
        }
        const std::size_t m = occupied.size();
        for (glm::vec3 &d : directions)
            d = glm::normalize(d);
        sums.assign(m, glm::vec3(0.0f));
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = 0; j < m; ++j)
                if (glm::dot(directions[i], directions[j]) >= threshold)
                    sums[i] += weighted[j];
        for (std::size_t k = 0; k < cornerSum.size(); ++k)
            if (cornerSlot[k] >= 0)
                cornerSum[k] = sums[std::size_t(cornerSlot[k])];
    }
};

// The output vertex of each (normal, colour, texture coordinate) at a big position, by hash
// rather than by comparing with every one made before.
struct VertexKey
{
    glm::vec3 normal, color;
    glm::vec2 uv;
    bool operator==(const VertexKey &o) const
    {
        return normal == o.normal && color == o.color && uv == o.uv;
    }
};
struct VertexKeyHash
{
    std::size_t operator()(const VertexKey &k) const
    {
        const float f[8] = {k.normal.x, k.normal.y, k.normal.z, k.color.x,
                            k.color.y,  k.color.z,  k.uv.x,     k.uv.y};
        std::uint64_t h = 0xcbf29ce484222325ull;
        for (float x : f) {
            std::uint32_t u;
            x = x == 0.0f ? 0.0f : x;
            std::memcpy(&u, &x, sizeof u);
            h = (h ^ u) * 0x100000001b3ull;
        }
        return std::size_t(h ^ (h >> 29));
    }
};

// A triangle's unit normal (0 for a sliver whose area is rounding noise: it has no direction
// worth averaging) and, when `angles` is given, the angle at each of its corners. One function
// for both paths below, so that they add the same numbers.
glm::vec3 triangleGeometry(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c,
                           float *angles = nullptr)
{
    const glm::vec3 ab = b - a, bc = c - b, ca = a - c;
    const glm::vec3 n = glm::cross(ab, c - a);
    const float length = glm::length(n);
    const float edge = std::max({glm::dot(ab, ab), glm::dot(bc, bc), glm::dot(ca, ca)});
    if (angles) {
        const float lab = glm::length(ab), lbc = glm::length(bc), lca = glm::length(ca);
        angles[0] = cornerAngle(ab, lab, -ca, lca);
        angles[1] = cornerAngle(bc, lbc, -ab, lab);
        angles[2] = cornerAngle(ca, lca, -bc, lbc);
    }
    return length > 1e-6f * edge && std::isfinite(length) ? n / length : glm::vec3(0.0f);
}

// The common smooth mesh, quickly and without the general loop's arrays: every position has one
// vertex, used by some triangle, and every position takes the fast path of the general loop
// in withGeneratedNormals (its faces lie within half the crease of their mean). Then each
// vertex keeps its place and gets the sum of its corners, added in the same order as the
// general loop adds them: the same mesh, bit for bit, without grouping the corners (positions
// of over 64 corners get the exact sum, where the general loop bins them). The triangles'
// normals and angles are computed where they are added, never stored (on a 10M-triangle scan
// the two arrays were 240 MB, written and read back: half of this function's time). Returns
// the normals, one a vertex, or nothing for any other mesh.
std::optional<std::vector<glm::vec3>> withoutSplits(const Mesh &mesh,
                                                    const std::vector<std::uint32_t> &position,
                                                    std::size_t cornerCount, float threshold,
                                                    float halfThreshold, std::size_t parts)
{
    const std::size_t vertexCount = mesh.vertexCount();
    const std::size_t triangleCount = cornerCount / 3;
    if (halfThreshold >= 1.0f) // flat or nearly: only exactly coplanar corners would fit
        return std::nullopt;
    for (std::size_t v = 0; v < vertexCount; ++v)
        if (position[v] != v)
            return std::nullopt;
    const std::uint32_t *index = mesh.indices.data();
    const glm::vec3 *p = mesh.positions.data();
    std::vector<glm::vec3> normals(vertexCount, glm::vec3(0.0f));
    std::atomic_bool fits{true};
    // Each part sums the corners of its own vertices, in corner order (no two parts write
    // the same vertex); a triangle with corners in two parts is computed by both.
    parallelFor(vertexCount, parts, [&](std::size_t first, std::size_t last, std::size_t) {
        const std::uint32_t span = std::uint32_t(last - first);
        auto mine = [&](std::uint32_t v) { return v - std::uint32_t(first) < span; };
        std::vector<std::uint8_t> used(span, 0);
        for (std::size_t t = 0; t < triangleCount; ++t) {
            const std::uint32_t *corner = index + 3 * t;
            if (!mine(corner[0]) && !mine(corner[1]) && !mine(corner[2]))
                continue;
            float angle[3];
            const glm::vec3 n = triangleGeometry(p[corner[0]], p[corner[1]], p[corner[2]], angle);
            for (int k = 0; k < 3; ++k)
                if (mine(corner[k])) {
                    normals[corner[k]] += angle[k] * n;
                    used[corner[k] - first] = 1;
                }
        }
        for (std::size_t v = first; v < last; ++v) {
            if (!used[v - first] || (threshold > -1.0f && normals[v] == glm::vec3(0.0f)))
                fits = false;
            normals[v] = unitOr(normals[v]);
        }
    });
    if (!fits)
        return std::nullopt;
    if (threshold > -1.0f)
        parallelFor(triangleCount, parts, [&](std::size_t first, std::size_t last, std::size_t) {
            for (std::size_t t = first; t < last && fits.load(std::memory_order_relaxed); ++t) {
                const std::uint32_t *corner = index + 3 * t;
                const glm::vec3 n = triangleGeometry(p[corner[0]], p[corner[1]], p[corner[2]]);
                if (n == glm::vec3(0.0f))
                    continue;
                for (int k = 0; k < 3; ++k)
                    if (glm::dot(n, normals[corner[k]]) < halfThreshold)
                        fits = false;
            }
        });
    if (!fits)
        return std::nullopt;
    return normals;
}

// The mesh again with these normals.
Mesh withNormals(const Mesh &mesh, std::vector<glm::vec3> normals, std::size_t cornerCount)
{
    Mesh out;
    out.positions = mesh.positions;
    out.normals = std::move(normals);
    if (mesh.colors.size() == mesh.vertexCount())
        out.colors = mesh.colors;
    if (mesh.uvs.size() == mesh.vertexCount())
        out.uvs = mesh.uvs;
    out.indices.assign(mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(cornerCount));
    return out;
}

} // namespace

std::optional<Mesh> withGeneratedNormals(const Mesh &mesh, float creaseDegrees,
                                         const std::atomic_bool *cancel,
                                         const std::vector<std::uint32_t> *weld)
{
    auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    const std::size_t vertexCount = mesh.vertexCount();
    const std::size_t cornerCount = mesh.indices.size() - mesh.indices.size() % 3;
    const std::size_t triangleCount = cornerCount / 3;

    // Big meshes are split over the machine's cores; small ones aren't worth a thread.
    const std::size_t parts =
        triangleCount < 50'000 ? 1
                               : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);

    // A small tolerance keeps coplanar triangles together at 0 degrees despite rounding.
    const float threshold = std::cos(glm::radians(std::clamp(creaseDegrees, 0.0f, 180.0f))) - 1e-5f;
    const float halfThreshold = halfCreaseCosine(creaseDegrees);
    std::vector<std::uint32_t> ownWeld; // unless the caller welded them already
    const std::vector<std::uint32_t> &position = givenOrOwnWeld(mesh.positions, weld, ownWeld);
    if (cancelled())
        return std::nullopt;
    if (std::optional<std::vector<glm::vec3>> smooth =
            withoutSplits(mesh, position, cornerCount, threshold, halfThreshold, parts)) {
        if (cancelled())
            return std::nullopt;
        std::vector<std::uint32_t>().swap(ownWeld); // before the mesh is copied with its normals
        return withNormals(mesh, std::move(*smooth), cornerCount);
    }
    if (cancelled())
        return std::nullopt;

    // Unit face normals and each corner's angle.
    std::vector<glm::vec3> faceNormal(triangleCount);
    std::vector<float> angle(cornerCount);
    parallelFor(triangleCount, parts, [&](std::size_t first, std::size_t last, std::size_t) {
        for (std::size_t t = first; t < last; ++t)
            faceNormal[t] = triangleGeometry(
                mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                mesh.positions[mesh.indices[3 * t + 2]], &angle[3 * t]);
    });
    if (cancelled())
        return std::nullopt;

    // The corners at each position, grouped (counting sort by the position's first vertex).
    std::vector<std::uint32_t> start(vertexCount + 1, 0);
    for (std::size_t c = 0; c < cornerCount; ++c)
        ++start[position[mesh.indices[c]] + 1];
    for (std::size_t v = 0; v < vertexCount; ++v)
        start[v + 1] += start[v];
    std::vector<std::uint32_t> corners(cornerCount);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t c = 0; c < cornerCount; ++c)
            corners[fill[position[mesh.indices[c]]]++] = std::uint32_t(c);
    }
    if (cancelled())
        return std::nullopt;

    // Each part makes the output vertices of its positions; the parts are joined after.
    const bool colors = mesh.colors.size() == vertexCount;
    const bool uvs = mesh.uvs.size() == vertexCount;
    std::vector<std::uint32_t> outIndex(cornerCount);
    std::vector<Mesh> out(parts);
    parallelFor(
        vertexCount, parts, [&](std::size_t firstGroup, std::size_t lastGroup, std::size_t part) {
            Mesh &o = out[part];
            o.positions.reserve(lastGroup - firstGroup);
            o.normals.reserve(lastGroup - firstGroup);
            std::vector<std::uint32_t> made; // output vertices of the current position
            std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> madeByKey; // big ones
            Bins bins;
            std::vector<glm::vec3> binnedSum;
            for (std::size_t group = firstGroup; group < lastGroup; ++group) {
                const std::uint32_t *begin = corners.data() + start[group];
                const std::uint32_t *end = corners.data() + start[group + 1];
                if (begin == end)
                    continue;
                if ((group & 0xffff) == 0 && cancelled())
                    return;
                const bool big = std::size_t(end - begin) > kBinnedCorners;
                glm::vec3 all(0.0f);
                for (const std::uint32_t *c = begin; c != end; ++c)
                    all += angle[*c] * faceNormal[*c / 3];
                const glm::vec3 allNormal = unitOr(all);
                // The fast path, taken by most positions of a smooth mesh: when every face
                // here lies within half the crease of their mean, each lies within the crease
                // of every other, so every corner's sum is the whole sum (the same additions
                // in the same order: the same normal, bit for bit) and needs no comparisons.
                bool oneNormal = threshold <= -1.0f;
                if (!oneNormal && all != glm::vec3(0.0f)) {
                    oneNormal = true;
                    for (const std::uint32_t *c = begin; c != end && oneNormal; ++c) {
                        const glm::vec3 &n = faceNormal[*c / 3]; // 0: in no corner's way
                        oneNormal = n == glm::vec3(0.0f) || glm::dot(n, allNormal) >= halfThreshold;
                    }
                }
                if (big && !oneNormal)
                    bins.sum(begin, end, faceNormal, angle, threshold, binnedSum);
                made.clear();
                madeByKey.clear();
                for (const std::uint32_t *c = begin; c != end; ++c) {
                    const glm::vec3 &own = faceNormal[*c / 3];
                    glm::vec3 normal = allNormal; // a degenerate triangle takes its neighbours'
                    if (!oneNormal && own != glm::vec3(0.0f)) {
                        glm::vec3 sum(0.0f);
                        if (big) {
                            sum = binnedSum[std::size_t(c - begin)];
                        } else {
                            for (const std::uint32_t *d = begin; d != end; ++d)
                                if (glm::dot(own, faceNormal[*d / 3]) >= threshold)
                                    sum += angle[*d] * faceNormal[*d / 3];
                        }
                        normal = unitOr(sum);
                    }
                    // Share an output vertex with an earlier corner at this position that has the
                    // same normal, colour and texture coordinates.
                    const std::uint32_t vertex = mesh.indices[*c];
                    std::uint32_t index = std::uint32_t(o.positions.size());
                    if (big) {
                        const VertexKey key{normal, colors ? mesh.colors[vertex] : glm::vec3(0.0f),
                                            uvs ? mesh.uvs[vertex] : glm::vec2(0.0f)};
                        index = madeByKey.try_emplace(key, index).first->second;
                    } else {
                        for (const std::uint32_t m : made)
                            if (o.normals[m] == normal &&
                                (!colors || o.colors[m] == mesh.colors[vertex]) &&
                                (!uvs || o.uvs[m] == mesh.uvs[vertex])) {
                                index = m;
                                break;
                            }
                    }
                    if (index == o.positions.size()) {
                        o.positions.push_back(mesh.positions[vertex]);
                        o.normals.push_back(normal);
                        if (colors)
                            o.colors.push_back(mesh.colors[vertex]);
                        if (uvs)
                            o.uvs.push_back(mesh.uvs[vertex]);
                        made.push_back(index);
                    }
                    outIndex[*c] = index; // local to the part until the join
                }
            }
        });
    if (cancelled())
        return std::nullopt;

    Mesh joined = std::move(out[0]);
    for (std::size_t part = 1; part < parts; ++part) {
        const std::uint32_t offset = std::uint32_t(joined.positions.size());
        const std::uint32_t *first = corners.data() + start[vertexCount * part / parts];
        const std::uint32_t *last = corners.data() + start[vertexCount * (part + 1) / parts];
        for (const std::uint32_t *c = first; c != last; ++c)
            outIndex[*c] += offset;
        const Mesh &o = out[part];
        joined.positions.insert(joined.positions.end(), o.positions.begin(), o.positions.end());
        joined.normals.insert(joined.normals.end(), o.normals.begin(), o.normals.end());
        joined.colors.insert(joined.colors.end(), o.colors.begin(), o.colors.end());
        joined.uvs.insert(joined.uvs.end(), o.uvs.begin(), o.uvs.end());
        out[part] = Mesh{};
    }
    joined.indices = std::move(outIndex);
    return joined;
}

} // namespace lb
