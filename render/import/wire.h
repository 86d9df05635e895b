#pragma once
// The stream the import helper (lightbench-import) writes on its stdout and the workbench
// reads: an 8-byte magic, then records of a fixed header and a payload. Plain C++ so the
// helper needs neither Qt nor the render library. Both ends run on the same machine, so
// numbers travel in the host's byte order.

#include <cstdint>

namespace lb::wire {

constexpr char kMagic[8] = {'L', 'B', 'M', 'E', 'S', 'H', '0', '1'};

enum class Record : std::uint32_t {
    Progress = 1,    // float fraction in [0, 1], then the stage as UTF-8
    Error = 2,       // UTF-8 message; the helper exits with kExitFailed after it
    Info = 3,        // UTF-8 "key=value" lines: meshes, skipped, seconds, peakKB, ...
    Material = 4,    // MaterialRecord
    Mesh = 5,        // MeshHeader, then the arrays it announces
    TexturePath = 6, // UTF-8 path of the diffuse texture, as the file names it
    TextureData = 7, // TextureHeader, then the texture's bytes (embedded in the model file)
    End = 8,         // empty; the stream is complete
    Warning = 9,     // UTF-8 line: something the mesh names was not used, and why
};

struct RecordHeader
{
    std::uint32_t type = 0;
    std::uint32_t reserved = 0;
    std::uint64_t size = 0; // payload bytes after this header
};

enum MeshFlags : std::uint32_t {
    kHasNormals = 1,
    kHasColors = 2,
    kHasUvs = 4,
};

// Followed by positions (3 floats per vertex), then normals, colours (3 floats each) and
// texture coordinates (2 floats) where the flags say so, then the indices (uint32, three
// per triangle).
struct MeshHeader
{
    std::uint64_t vertexCount = 0;
    std::uint64_t indexCount = 0;
    std::uint32_t flags = 0;
    std::uint32_t reserved = 0;
};

enum MaterialFlags : std::uint32_t {
    kHasAmbient = 1,
    kHasDiffuse = 2,
    kHasSpecular = 4,
    kHasShininess = 8,
};

struct MaterialRecord
{
    float ka[3] = {0, 0, 0};
    float kd[3] = {0, 0, 0};
    float ks[3] = {0, 0, 0};
    float shininess = 0;
    std::uint32_t present = 0; // MaterialFlags
    std::uint32_t reserved = 0;
};

// width and height 0: the bytes are a compressed image (PNG, JPEG, ...) and `format` is
// Assimp's hint ("png", "jpg"); otherwise width * height texels of 4 bytes, B, G, R, A.
struct TextureHeader
{
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    char format[8] = {};
};

// The largest mesh the workbench accepts: 32-bit indices, and a bound on what one record
// may make the workbench allocate.
constexpr std::uint64_t kMaxVertices = 0xffffffffull;
constexpr std::uint64_t kMaxRecordBytes = 16ull << 30;

// The helper's exit codes besides 0 (success).
constexpr int kExitUsage = 2;
constexpr int kExitFailed = 3;      // an Error record says why
constexpr int kExitOutOfMemory = 4; // an Error record says so too

} // namespace lb::wire
