#pragma once
// The second half of the import helper's work: the meshes read (an Assimp scene, or what a fast
// reader made) written to the import stream (wire.h) as one mesh: every part with its transform
// applied, centred and scaled to fit the view, then the largest mesh's material and diffuse
// texture, figures about the load (Info) and the End record. Plain C++: the helper only.

#include "wire_writer.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct aiFace;
struct aiScene;

namespace lb {

// Progress as the stream's Progress records carry it: a fraction in [0, 1] and the stage.
using ImportProgress = std::function<void(float fraction, const char *stage)>;

// One mesh as the stream takes it, over arrays someone else holds: Assimp's (aiMesh) or the
// fast readers' (fast_mesh_readers.h), so that neither copies into the other's form.
struct StreamMesh
{
    std::uint32_t vertexCount = 0;
    const float *positions = nullptr; // x, y, z a vertex; none: the mesh draws nothing
    const float *normals = nullptr;   // x, y, z a vertex, or none
    const float *colors = nullptr;    // r, g, b first in each colorStride floats, or none
    std::size_t colorStride = 3;
    const float *uvs = nullptr; // s, t first in each uvStride floats, or none
    std::size_t uvStride = 2;
    std::uint32_t faceCount = 0;
    const aiFace *faces = nullptr;            // Assimp's faces, any number of corners, or
    const std::uint32_t *triangles = nullptr; // three corners a face
};

// A mesh where a node puts it.
struct StreamPart
{
    StreamMesh mesh;
    glm::mat4 transform{1.0f};
};

// What the stream says beside the parts.
struct StreamExtras
{
    std::uint64_t skippedFaces = 0;  // faces the reader dropped before they reached a part
    std::size_t skippedMeshRefs = 0; // nodes' references to meshes that are not there
    std::string reader;              // who read the file, for the Info record: "assimp", "ply"
    // Sends the Material (and texture) records of the part given: the largest drawn.
    std::function<void(std::size_t part, wire::Writer &)> sendMaterial;
};

// Vertices whose transformed position is not finite (NaN, +-inf, or a finite value that the
// node transform carries past float's range) are dropped, with every triangle that uses one:
// a triangle cannot be drawn, lit or framed with such a corner. The Info record counts them
// ("nonFinite", "droppedTriangles"). Non-finite normals make the file's normals unusable
// (counted as "nonFiniteNormals"); the workbench generates normals then.
// Returns the helper's exit code: 0, or wire::kExitFailed after an Error record.
int writeParts(const std::vector<StreamPart> &parts, const StreamExtras &extras, wire::Writer &out,
               const ImportProgress &progress, double readSeconds);

// An Assimp scene as parts: each node's meshes with the node's transform.
int writeScene(const aiScene &scene, wire::Writer &out, const ImportProgress &progress,
               double readSeconds);

} // namespace lb
