#include "scene_stream.h"

#include "resident_memory.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

namespace lb {

namespace {

using wire::Record;

constexpr std::uint32_t kDropped = std::numeric_limits<std::uint32_t>::max();

glm::mat4 toGlm(const aiMatrix4x4 &m)
{
    // Assimp stores rows; GLM takes columns.
    return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                     m.b4, m.c4, m.d4);
}

// One part as it is drawn, and what of it is drawn.
struct Instance
{
    const StreamMesh *mesh;
    glm::mat4 transform;
    glm::mat3 normalTransform;
    // Empty: every vertex is kept. Else each vertex's index among the kept ones, or kDropped
    // (its transformed position is not finite); only made for meshes that drop some.
    std::vector<std::uint32_t> remap;
    std::uint32_t keptVertices = 0;
    std::uint64_t triangles = 0; // kept: triangles whose corners are all kept

    bool used() const { return triangles > 0; }
    bool kept(unsigned v) const { return remap.empty() || remap[v] != kDropped; }
    bool kept(const std::uint32_t (&c)[3]) const { return kept(c[0]) && kept(c[1]) && kept(c[2]); }
};

bool finite(const glm::vec3 &v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Face `f`'s corners, when it is a triangle whose corners are all vertices of the mesh.
bool triangle(const StreamMesh &m, std::uint32_t f, std::uint32_t (&c)[3])
{
    if (m.triangles) {
        const std::uint32_t *t = m.triangles + 3 * std::size_t(f);
        c[0] = t[0];
        c[1] = t[1];
        c[2] = t[2];
    } else {
        const aiFace &face = m.faces[f];
        if (face.mNumIndices != 3)
            return false;
        c[0] = face.mIndices[0];
        c[1] = face.mIndices[1];
        c[2] = face.mIndices[2];
    }
    return c[0] < m.vertexCount && c[1] < m.vertexCount && c[2] < m.vertexCount;
}

glm::vec3 position(const Instance &in, unsigned v)
{
    const float *p = in.mesh->positions + 3 * std::size_t(v);
    return glm::vec3(in.transform * glm::vec4(p[0], p[1], p[2], 1.0f));
}

// What is kept of one instance, and its kept vertices' bounds (in double: finite floats near
// the ends of their range would make an infinite extent in float).
struct Counts
{
    std::uint64_t droppedVertices = 0, droppedTriangles = 0, skippedFaces = 0;
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
};

void plan(Instance &in, Counts &counts)
{
    const StreamMesh &m = *in.mesh;
    if (!m.positions) {
        counts.skippedFaces += m.faceCount;
        return;
    }
    // The corners that are not finite: most meshes have none, and then this pass is all
    // there is (the bounds come with it).
    glm::dvec3 lo = counts.lo, hi = counts.hi;
    for (unsigned v = 0; v < m.vertexCount; ++v) {
        const glm::vec3 t = position(in, v);
        if (finite(t)) {
            lo = glm::min(lo, glm::dvec3(t));
            hi = glm::max(hi, glm::dvec3(t));
            continue;
        }
        if (in.remap.empty())
            in.remap.assign(m.vertexCount, 0); // 0: finite, not yet used
        in.remap[v] = kDropped;
        ++counts.droppedVertices;
    }
    constexpr std::uint32_t kUsed = 1;
    std::uint64_t dropped = 0;
    std::uint32_t c[3];
    for (std::uint32_t f = 0; f < m.faceCount; ++f) {
        if (!triangle(m, f, c)) {
            ++counts.skippedFaces;
        } else if (in.kept(c)) {
            ++in.triangles;
            if (!in.remap.empty())
                for (std::uint32_t k : c)
                    in.remap[k] = kUsed;
        } else {
            ++dropped;
        }
    }
    counts.droppedTriangles += dropped;
    in.keptVertices = m.vertexCount;
    if (!in.remap.empty()) {
        // Only the corners of the triangles kept stay, so that the frame is what is drawn:
        // a file read without joining vertices has a copy of each corner per face.
        lo = counts.lo;
        hi = counts.hi;
        std::uint32_t next = 0;
        for (unsigned v = 0; v < m.vertexCount; ++v) {
            if (in.remap[v] != kUsed) {
                in.remap[v] = kDropped;
                continue;
            }
            in.remap[v] = next++;
            const glm::dvec3 t(position(in, v));
            lo = glm::min(lo, t);
            hi = glm::max(hi, t);
        }
        in.keptVertices = next;
    }
    if (in.used()) { // an instance with nothing to draw does not move the frame
        counts.lo = lo;
        counts.hi = hi;
    }
}

// Whether any kept triangle has an area worth a pixel at any size the workbench draws (a
// millionth of the largest extent on each side): a file whose triangles all collapse to
// lines or points draws nothing at all. Stops at the first such triangle.
bool anyArea(const std::vector<Instance> &list, double largestExtent)
{
    const double tiny = 1e-12 * largestExtent * largestExtent;
    for (const Instance &in : list) {
        if (!in.used())
            continue;
        std::uint32_t k[3];
        for (std::uint32_t f = 0; f < in.mesh->faceCount; ++f) {
            if (!triangle(*in.mesh, f, k) || !in.kept(k))
                continue;
            const glm::dvec3 a = position(in, k[0]), b = position(in, k[1]), c = position(in, k[2]);
            if (glm::length(glm::cross(b - a, c - a)) > tiny)
                return true;
        }
    }
    return false;
}

// The file's normals are used only when every drawn mesh has them and they are all usable;
// `nonFinite` counts those that are NaN or infinite.
bool usableNormals(const std::vector<Instance> &list, std::uint64_t &nonFinite)
{
    bool usable = true;
    for (const Instance &in : list) {
        if (!in.used())
            continue;
        if (!in.mesh->normals) {
            usable = false;
            continue;
        }
        for (unsigned v = 0; v < in.mesh->vertexCount; ++v) {
            const float *n = in.mesh->normals + 3 * std::size_t(v);
            const glm::vec3 g(n[0], n[1], n[2]);
            if (!in.kept(v))
                continue;
            if (!finite(g))
                ++nonFinite;
            if (!finite(g) || glm::dot(g, g) < 1e-12f)
                usable = false;
        }
    }
    return usable;
}

void sendMaterial(const aiScene &scene, const aiMesh &mesh, wire::Writer &out)
{
    if (mesh.mMaterialIndex >= scene.mNumMaterials || !scene.mMaterials[mesh.mMaterialIndex])
        return;
    const aiMaterial &m = *scene.mMaterials[mesh.mMaterialIndex];
    wire::MaterialRecord r;
    aiColor3D c;
    auto colour = [&](const char *key, unsigned type, unsigned index, float *to,
                      std::uint32_t flag) {
        if (m.Get(key, type, index, c) == AI_SUCCESS && std::isfinite(c.r) && std::isfinite(c.g) &&
            std::isfinite(c.b)) {
            to[0] = c.r;
            to[1] = c.g;
            to[2] = c.b;
            r.present |= flag;
        }
    };
    colour(AI_MATKEY_COLOR_AMBIENT, r.ka, wire::kHasAmbient);
    colour(AI_MATKEY_COLOR_DIFFUSE, r.kd, wire::kHasDiffuse);
    colour(AI_MATKEY_COLOR_SPECULAR, r.ks, wire::kHasSpecular);
    float shininess = 0.0f;
    if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess)) {
        r.shininess = shininess;
        r.present |= wire::kHasShininess;
    }
    if (r.present)
        out.record(Record::Material, &r, sizeof r);

    aiString path;
    if (m.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS &&
        m.GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS)
        return;
    if (const aiTexture *t = scene.GetEmbeddedTexture(path.C_Str())) {
        wire::TextureHeader h;
        std::uint64_t bytes = 0;
        if (t->mHeight == 0) { // compressed: mWidth is the byte count
            bytes = t->mWidth;
        } else {
            h.width = t->mWidth;
            h.height = t->mHeight;
            bytes = std::uint64_t(t->mWidth) * t->mHeight * 4;
        }
        std::memcpy(h.format, t->achFormatHint, std::min(sizeof h.format, sizeof t->achFormatHint));
        if (!t->pcData || bytes == 0)
            return;
        out.begin(Record::TextureData, sizeof h + bytes);
        out.write(&h, sizeof h);
        out.write(t->pcData, bytes);
    } else if (path.length > 0) {
        out.text(Record::TexturePath, path.C_Str());
    }
}

// Values (floats or indices) sent a chunk at a time: the wire writer's buffer, so that a
// whole chunk goes out directly.
constexpr std::size_t kChunkValues = wire::kBufferBytes / 4;
template <typename T> void sendChunk(std::vector<T> &chunk, wire::Writer &out)
{
    static_assert(sizeof(T) == 4);
    out.write(chunk.data(), chunk.size() * sizeof(T));
    chunk.clear();
}

} // namespace

int writeParts(const std::vector<StreamPart> &parts, const StreamExtras &extras, wire::Writer &out,
               const ImportProgress &progress, double readSeconds)
{
    std::vector<Instance> list;
    list.reserve(parts.size());
    for (const StreamPart &p : parts)
        list.push_back(
            {&p.mesh, p.transform, glm::inverseTranspose(glm::mat3(p.transform)), {}, 0, 0});

    // Pass 1: what is kept, the counts and the bounding box of the kept positions.
    Counts counts;
    counts.skippedFaces = extras.skippedFaces;
    std::uint64_t vertexCount = 0, triangleCount = 0;
    bool colors = false, uvs = false;
    const Instance *largest = nullptr;
    for (Instance &in : list) {
        plan(in, counts);
        if (!in.used())
            continue;
        if (!largest || in.triangles > largest->triangles)
            largest = &in;
        vertexCount += in.keptVertices;
        triangleCount += in.triangles;
        colors = colors || in.mesh->colors;
        uvs = uvs || in.mesh->uvs;
    }
    if (triangleCount == 0) {
        std::ostringstream s;
        s << "the file holds no triangles";
        if (counts.droppedTriangles)
            s << " with finite coordinates (" << counts.droppedVertices
              << " vertices with non-finite coordinates)";
        else if (counts.skippedFaces)
            s << " (" << counts.skippedFaces << " points, lines or broken faces)";
        return out.fail(s.str());
    }
    if (vertexCount > wire::kMaxVertices)
        return out.fail("too many vertices for 32-bit indices");
    const glm::dvec3 centre = 0.5 * (counts.lo + counts.hi);
    const glm::dvec3 extent = counts.hi - counts.lo;
    const double largestExtent = std::max(extent.x, std::max(extent.y, extent.z));
    if (!(largestExtent > 0.0) || !anyArea(list, largestExtent)) {
        std::ostringstream s;
        s << "nothing to draw: the file's " << triangleCount
          << (triangleCount == 1 ? " triangle has" : " triangles have") << " no area ("
          << (largestExtent == 0.0 ? "every vertex is at the same point"
              : triangleCount == 1 ? "its corners lie on a line"
                                   : "the corners of each lie on a line")
          << ")";
        return out.fail(s.str());
    }
    progress(0.85f, "converting");

    std::uint64_t nonFiniteNormals = 0;
    const bool normals = usableNormals(list, nonFiniteNormals);
    const double scale = largestExtent > 0.0
                             ? 2.0 / largestExtent
                             : 1.0; // fit in the cube [-1, 1], as the built-in shapes do

    wire::MeshHeader header;
    header.vertexCount = vertexCount;
    header.indexCount = triangleCount * 3;
    header.flags = (normals ? std::uint32_t(wire::kHasNormals) : 0u) |
                   (colors ? std::uint32_t(wire::kHasColors) : 0u) |
                   (uvs ? std::uint32_t(wire::kHasUvs) : 0u);
    const std::uint64_t perVertex = 12 + (normals ? 12 : 0) + (colors ? 12 : 0) + (uvs ? 8 : 0);
    out.begin(Record::Mesh, sizeof header + vertexCount * perVertex + header.indexCount * 4);
    out.write(&header, sizeof header);

    // One pass per array, each sent a chunk at a time, so that no array is gathered in memory
    // before it goes out (a 1M-triangle file's indices alone are 12 MB, every page of it a
    // fault on the helper's path). A chunk is as big as the writer's buffer: it goes out
    // directly, not copied into the buffer.
    std::vector<float> chunk;
    chunk.reserve(kChunkValues + 3);
    auto emit = [&](auto &&perVertexValue) {
        for (const Instance &in : list) {
            if (!in.used())
                continue;
            for (unsigned v = 0; v < in.mesh->vertexCount; ++v) {
                if (in.kept(v))
                    perVertexValue(in, v, chunk);
                if (chunk.size() >= kChunkValues)
                    sendChunk(chunk, out);
            }
        }
        sendChunk(chunk, out);
    };
    emit([&](const Instance &in, unsigned v, std::vector<float> &c) {
        const glm::vec3 t((glm::dvec3(position(in, v)) - centre) * scale);
        c.insert(c.end(), {t.x, t.y, t.z});
    });
    if (normals)
        emit([&](const Instance &in, unsigned v, std::vector<float> &c) {
            const float *n = in.mesh->normals + 3 * std::size_t(v);
            glm::vec3 t = in.normalTransform * glm::vec3(n[0], n[1], n[2]);
            const float length = glm::length(t);
            t = length > 0.0f && std::isfinite(length) ? t / length : glm::vec3(0, 0, 1);
            c.insert(c.end(), {t.x, t.y, t.z});
        });
    if (colors)
        emit([&](const Instance &in, unsigned v, std::vector<float> &c) {
            glm::vec3 t(1.0f);
            if (const float *col = in.mesh->colors) {
                col += in.mesh->colorStride * v;
                t = glm::clamp(glm::vec3(col[0], col[1], col[2]), 0.0f, 1.0f);
            }
            if (!finite(t))
                t = glm::vec3(1.0f);
            c.insert(c.end(), {t.x, t.y, t.z});
        });
    if (uvs)
        emit([&](const Instance &in, unsigned v, std::vector<float> &c) {
            float s = 0.0f, t = 0.0f;
            if (const float *uv = in.mesh->uvs) {
                uv += in.mesh->uvStride * v;
                s = std::isfinite(uv[0]) ? uv[0] : 0.0f;
                t = std::isfinite(uv[1]) ? uv[1] : 0.0f;
            }
            c.insert(c.end(), {s, t});
        });
    std::vector<std::uint32_t> indices;
    indices.reserve(kChunkValues + 3);
    std::uint32_t base = 0;
    for (const Instance &in : list) {
        if (!in.used())
            continue;
        auto index = [&](unsigned i) { return base + (in.remap.empty() ? i : in.remap[i]); };
        std::uint32_t c[3];
        for (std::uint32_t f = 0; f < in.mesh->faceCount; ++f) {
            if (triangle(*in.mesh, f, c) && in.kept(c))
                indices.insert(indices.end(), {index(c[0]), index(c[1]), index(c[2])});
            if (indices.size() >= kChunkValues)
                sendChunk(indices, out);
        }
        base += in.keptVertices;
    }
    sendChunk(indices, out);

    if (largest && extras.sendMaterial)
        extras.sendMaterial(std::size_t(largest - list.data()), out);
    std::ostringstream info;
    info << "meshes=" << list.size() << "\nskippedFaces=" << counts.skippedFaces
         << "\nnonFinite=" << counts.droppedVertices
         << "\ndroppedTriangles=" << counts.droppedTriangles
         << "\nnonFiniteNormals=" << nonFiniteNormals
         << "\nskippedMeshRefs=" << extras.skippedMeshRefs << "\nfileNormals=" << (normals ? 1 : 0)
         << "\nseconds=" << readSeconds << "\nreader=" << extras.reader
         << "\npeakKB=" << peakResidentKB() << "\n";
    out.text(Record::Info, info.str());
    progress(1.0f, "done");
    out.record(Record::End, nullptr, 0);
    out.flush();
    return out.ok() ? 0 : wire::kExitFailed;
}

namespace {

// Each node's meshes with the node's transform, walked from the root.
std::vector<StreamPart> sceneParts(const aiScene &scene, std::vector<const aiMesh *> &meshes,
                                   std::size_t &skippedMeshRefs)
{
    std::vector<StreamPart> parts;
    std::vector<std::pair<const aiNode *, glm::mat4>> stack;
    if (scene.mRootNode)
        stack.emplace_back(scene.mRootNode, glm::mat4(1.0f));
    constexpr std::size_t kMaxNodes = 10'000'000; // a broken file's node graph may loop
    std::size_t visited = 0;
    while (!stack.empty() && ++visited < kMaxNodes) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const glm::mat4 global = parent * toGlm(node->mTransformation);
        for (unsigned i = 0; i < node->mNumMeshes; ++i) {
            const unsigned index = node->mMeshes[i];
            if (index >= scene.mNumMeshes || !scene.mMeshes[index]) {
                ++skippedMeshRefs;
                continue;
            }
            const aiMesh &m = *scene.mMeshes[index];
            StreamMesh s;
            // aiVector3D and aiColor4D are plain floats in a row (ai_real is float here).
            static_assert(sizeof(aiVector3D) == 3 * sizeof(float));
            static_assert(sizeof(aiColor4D) == 4 * sizeof(float));
            s.vertexCount = m.mNumVertices;
            s.positions = reinterpret_cast<const float *>(m.mVertices);
            s.normals = reinterpret_cast<const float *>(m.mNormals);
            s.colors = reinterpret_cast<const float *>(m.mColors[0]);
            s.colorStride = 4;
            s.uvs = reinterpret_cast<const float *>(m.mTextureCoords[0]);
            s.uvStride = 3;
            s.faceCount = m.mFaces ? m.mNumFaces : 0;
            s.faces = m.mFaces;
            parts.push_back({s, global});
            meshes.push_back(&m);
        }
        for (unsigned i = 0; i < node->mNumChildren; ++i)
            if (node->mChildren[i])
                stack.emplace_back(node->mChildren[i], global);
    }
    return parts;
}

} // namespace

int writeScene(const aiScene &scene, wire::Writer &out, const ImportProgress &progress,
               double readSeconds)
{
    std::vector<const aiMesh *> meshes; // each part's
    StreamExtras extras;
    const std::vector<StreamPart> parts = sceneParts(scene, meshes, extras.skippedMeshRefs);
    extras.reader = "assimp";
    extras.sendMaterial = [&](std::size_t part, wire::Writer &w) {
        sendMaterial(scene, *meshes[part], w);
    };
    return writeParts(parts, extras, out, progress, readSeconds);
}

} // namespace lb
