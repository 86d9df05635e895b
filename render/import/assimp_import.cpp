#include "assimp_import.h"

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <vector>

#include <sys/resource.h>

namespace lb {

namespace {

using wire::Record;

// Assimp reports its progress here; it goes out as Progress records, at most one per
// percent, and the reading stage takes the first 80 % of the bar.
class Progress : public Assimp::ProgressHandler
{
public:
    explicit Progress(wire::Writer &out) : m_out(out) {}
    bool Update(float percentage) override
    {
        if (percentage >= 0.0f)
            send(0.8f * std::min(percentage, 1.0f), "reading");
        return m_out.ok(); // stop reading when the workbench went away
    }
    void send(float fraction, const char *stage)
    {
        if (fraction < m_last + 0.01f && fraction < 1.0f)
            return;
        m_last = fraction;
        std::string payload(sizeof fraction, '\0');
        std::memcpy(payload.data(), &fraction, sizeof fraction);
        payload += stage;
        m_out.text(Record::Progress, payload);
        m_out.flush();
    }

private:
    wire::Writer &m_out;
    float m_last = -1.0f;
};

glm::mat4 toGlm(const aiMatrix4x4 &m)
{
    // Assimp stores rows; GLM takes columns.
    return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                     m.b4, m.c4, m.d4);
}

// One mesh as a node draws it.
struct Instance
{
    const aiMesh *mesh;
    glm::mat4 transform;
    glm::mat3 normalTransform;
};

bool finite(const glm::vec3 &v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::vector<Instance> instances(const aiScene &scene, std::size_t &skippedMeshRefs)
{
    std::vector<Instance> result;
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
            result.push_back(
                {scene.mMeshes[index], global, glm::inverseTranspose(glm::mat3(global))});
        }
        for (unsigned i = 0; i < node->mNumChildren; ++i)
            if (node->mChildren[i])
                stack.emplace_back(node->mChildren[i], global);
    }
    return result;
}

bool isTriangle(const aiFace &face, unsigned vertexCount)
{
    return face.mNumIndices == 3 && face.mIndices[0] < vertexCount &&
           face.mIndices[1] < vertexCount && face.mIndices[2] < vertexCount;
}

// The file's normals are used only when every mesh has them and they are all usable.
bool usableNormals(const std::vector<Instance> &list)
{
    for (const Instance &in : list) {
        if (!in.mesh->mNormals)
            return false;
        for (unsigned v = 0; v < in.mesh->mNumVertices; ++v) {
            const aiVector3D &n = in.mesh->mNormals[v];
            const glm::vec3 g(n.x, n.y, n.z);
            if (!finite(g) || glm::dot(g, g) < 1e-12f)
                return false;
        }
    }
    return true;
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

long peakKilobytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

int fail(wire::Writer &out, const std::string &message, int code = wire::kExitFailed)
{
    out.text(Record::Error, message);
    out.flush();
    return code;
}

int convert(const aiScene &scene, Progress &progress, wire::Writer &out, double seconds)
{
    std::size_t skippedMeshRefs = 0;
    const std::vector<Instance> list = instances(scene, skippedMeshRefs);

    // Pass 1: counts and the bounding box of the transformed positions.
    std::uint64_t vertexCount = 0, triangleCount = 0, skippedFaces = 0, nonFinite = 0;
    bool colors = false, uvs = false;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    const Instance *largest = nullptr;
    std::uint64_t largestTriangles = 0;
    for (const Instance &in : list) {
        const aiMesh &m = *in.mesh;
        std::uint64_t triangles = 0;
        for (unsigned f = 0; f < m.mNumFaces; ++f)
            isTriangle(m.mFaces[f], m.mNumVertices) ? ++triangles : ++skippedFaces;
        if (triangles == 0 || !m.mVertices)
            continue;
        if (triangles > largestTriangles) {
            largest = &in;
            largestTriangles = triangles;
        }
        vertexCount += m.mNumVertices;
        triangleCount += triangles;
        colors = colors || m.mColors[0];
        uvs = uvs || m.mTextureCoords[0];
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            const aiVector3D &p = m.mVertices[v];
            const glm::vec3 t(in.transform * glm::vec4(p.x, p.y, p.z, 1.0f));
            if (!finite(t)) {
                ++nonFinite;
                continue;
            }
            lo = glm::min(lo, t);
            hi = glm::max(hi, t);
        }
    }
    if (triangleCount == 0) {
        std::ostringstream s;
        s << "the file holds no triangles";
        if (skippedFaces)
            s << " (" << skippedFaces << " points, lines or broken faces)";
        return fail(out, s.str());
    }
    if (vertexCount > wire::kMaxVertices)
        return fail(out, "too many vertices for 32-bit indices");
    progress.send(0.85f, "converting");

    const bool normals = usableNormals(list);
    const glm::vec3 centre = nonFinite == vertexCount ? glm::vec3(0.0f) : 0.5f * (lo + hi);
    const glm::vec3 extent = hi - lo;
    const float largestExtent = std::max(extent.x, std::max(extent.y, extent.z));
    const float scale = std::isfinite(largestExtent) && largestExtent > 0.0f
                            ? 2.0f / largestExtent
                            : 1.0f; // fit in the cube [-1, 1], as the built-in shapes do

    auto used = [](const aiMesh &m) {
        if (!m.mVertices)
            return false;
        for (unsigned f = 0; f < m.mNumFaces; ++f)
            if (isTriangle(m.mFaces[f], m.mNumVertices))
                return true;
        return false;
    };

    wire::MeshHeader header;
    header.vertexCount = vertexCount;
    header.indexCount = triangleCount * 3;
    header.flags = (normals ? std::uint32_t(wire::kHasNormals) : 0u) |
                   (colors ? std::uint32_t(wire::kHasColors) : 0u) |
                   (uvs ? std::uint32_t(wire::kHasUvs) : 0u);
    const std::uint64_t perVertex = 12 + (normals ? 12 : 0) + (colors ? 12 : 0) + (uvs ? 8 : 0);
    out.begin(Record::Mesh, sizeof header + vertexCount * perVertex + header.indexCount * 4);
    out.write(&header, sizeof header);

    // One pass per array, so nothing is gathered in memory before it goes out.
    std::vector<float> chunk;
    auto emit = [&](auto &&perVertexValue, int components) {
        for (const Instance &in : list) {
            if (!used(*in.mesh))
                continue;
            chunk.clear();
            chunk.reserve(std::size_t(in.mesh->mNumVertices) * std::size_t(components));
            for (unsigned v = 0; v < in.mesh->mNumVertices; ++v)
                perVertexValue(in, v, chunk);
            out.write(chunk.data(), chunk.size() * sizeof(float));
        }
    };
    emit(
        [&](const Instance &in, unsigned v, std::vector<float> &c) {
            const aiVector3D &p = in.mesh->mVertices[v];
            glm::vec3 t(in.transform * glm::vec4(p.x, p.y, p.z, 1.0f));
            t = finite(t) ? (t - centre) * scale : glm::vec3(0.0f);
            c.insert(c.end(), {t.x, t.y, t.z});
        },
        3);
    if (normals)
        emit(
            [&](const Instance &in, unsigned v, std::vector<float> &c) {
                const aiVector3D &n = in.mesh->mNormals[v];
                glm::vec3 t = in.normalTransform * glm::vec3(n.x, n.y, n.z);
                const float length = glm::length(t);
                t = length > 0.0f && std::isfinite(length) ? t / length : glm::vec3(0, 0, 1);
                c.insert(c.end(), {t.x, t.y, t.z});
            },
            3);
    if (colors)
        emit(
            [&](const Instance &in, unsigned v, std::vector<float> &c) {
                glm::vec3 t(1.0f);
                if (const aiColor4D *col = in.mesh->mColors[0])
                    t = glm::clamp(glm::vec3(col[v].r, col[v].g, col[v].b), 0.0f, 1.0f);
                if (!finite(t))
                    t = glm::vec3(1.0f);
                c.insert(c.end(), {t.x, t.y, t.z});
            },
            3);
    if (uvs)
        emit(
            [&](const Instance &in, unsigned v, std::vector<float> &c) {
                float s = 0.0f, t = 0.0f;
                if (const aiVector3D *uv = in.mesh->mTextureCoords[0]) {
                    s = std::isfinite(uv[v].x) ? uv[v].x : 0.0f;
                    t = std::isfinite(uv[v].y) ? uv[v].y : 0.0f;
                }
                c.insert(c.end(), {s, t});
            },
            2);
    std::vector<std::uint32_t> indices;
    std::uint32_t base = 0;
    for (const Instance &in : list) {
        const aiMesh &m = *in.mesh;
        if (!used(m))
            continue;
        indices.clear();
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace &face = m.mFaces[f];
            if (isTriangle(face, m.mNumVertices))
                indices.insert(indices.end(), {base + face.mIndices[0], base + face.mIndices[1],
                                               base + face.mIndices[2]});
        }
        out.write(indices.data(), indices.size() * sizeof(std::uint32_t));
        base += m.mNumVertices;
    }

    if (largest)
        sendMaterial(scene, *largest->mesh, out);
    std::ostringstream info;
    info << "meshes=" << list.size() << "\nskippedFaces=" << skippedFaces
         << "\nnonFinite=" << nonFinite << "\nskippedMeshRefs=" << skippedMeshRefs
         << "\nfileNormals=" << (normals ? 1 : 0) << "\nseconds=" << seconds
         << "\npeakKB=" << peakKilobytes() << "\n";
    out.text(Record::Info, info.str());
    progress.send(1.0f, "done");
    out.record(Record::End, nullptr, 0);
    out.flush();
    return out.ok() ? 0 : wire::kExitFailed;
}

std::string outOfMemory(long long limitMB)
{
    std::ostringstream s;
    s << "out of memory: reading this file needs more than the import memory limit (" << limitMB
      << " MB)";
    return s.str();
}

} // namespace

int importToStream(const std::string &path, wire::Writer &out, long long memoryLimitMB)
{
    try {
        // Not deleted in the normal build: the helper exits right after this, and the system
        // takes the pages back faster than the importer frees a big scene's million small
        // face arrays. The sanitizer build deletes it, so its leak check has nothing to excuse.
        static std::unique_ptr<Assimp::Importer> owner;
        owner = std::make_unique<Assimp::Importer>();
        Assimp::Importer &importer = *owner;
#ifndef LIGHTBENCH_SANITIZE
        struct Keep
        {
            ~Keep() { owner.release(); }
        } keep;
#endif
        auto *progress = new Progress(out); // the importer owns it
        importer.SetProgressHandler(progress);
        // Plain reading plus triangulation: joining identical vertices costs ~6x the time
        // and 5x the memory on big files, and normals are the workbench's job.
        const auto start = std::chrono::steady_clock::now();
        const aiScene *scene = importer.ReadFile(path, aiProcess_Triangulate);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!scene) {
            std::string error = importer.GetErrorString();
            if (error.find("bad_alloc") != std::string::npos)
                return fail(out, outOfMemory(memoryLimitMB), wire::kExitOutOfMemory);
            return fail(out, error.empty() ? "Assimp could not read the file" : error);
        }
        if (!scene->mMeshes || scene->mNumMeshes == 0)
            return fail(out, "the file holds no meshes");
        return convert(*scene, *progress, out, seconds);
    } catch (const std::bad_alloc &) {
        return fail(out, outOfMemory(memoryLimitMB), wire::kExitOutOfMemory);
    } catch (const std::exception &e) {
        return fail(out, std::string("import failed: ") + e.what());
    }
}

std::string assimpExtensions()
{
    std::string list;
    Assimp::Importer().GetExtensionList(list);
    return list;
}

} // namespace lb
