#pragma once
// What a scene may ask of this machine's memory, checked before any of its meshes is built
// (issue 29: 32 spheres at tessellation 2000 took 8.9 GB and 41 s to open; 32 tori aborted
// on std::bad_alloc). Each object's mesh is counted as it will be held while it is drawn: the
// CPU copy (positions, normals, colours, texture coordinates, indices; kept for the probe)
// and the driver's copy (normals as vec4). A scene over the budget has the tessellation of
// the objects asking most lowered, all to one value, until it fits; the others keep theirs.

#include "scene.h"

#include <QString>

#include <cstdint>
#include <map>

namespace lb {

// A loaded mesh file as the budget counts it; files not loaded yet count as nothing (their
// objects draw their shapes meanwhile, and those are counted).
struct MeshFileSize
{
    std::uint64_t vertices = 0, triangles = 0;
    bool hasNormals = true;
};
using MeshFileSizes = std::map<QString, MeshFileSize>; // by path, as ObjectSettings names it

struct MeshCost
{
    std::uint64_t triangles = 0;
    std::uint64_t bytes = 0; // CPU and driver copies together
};

// Bytes one vertex and one triangle take: CPU 12 + 12 + 12 + 8, driver 12 + 16 + 12 + 8; and
// three 32-bit indices in each. Checked against the process: 32 spheres at 2000 (128 M
// triangles, 64 M vertices) measured 8.9 GB at its peak, this says 8.4 GB.
constexpr std::uint64_t kBytesPerVertex = 92;
constexpr std::uint64_t kBytesPerTriangle = 24;

struct MeshBudget
{
    std::uint64_t bytes = 0;        // what all objects' meshes together may take
    std::uint64_t machineBytes = 0; // the physical memory it was derived from
};

// Physical memory (sysconf; /proc/meminfo's MemTotal where sysconf cannot say; 8 GB where
// neither can).
std::uint64_t machineMemoryBytes();
// A quarter of the machine's memory, and never more than 768 MB: the scene is built twice,
// in the window and in the trial helper that tries the user's program on it (render/trial),
// and each process takes about 200 MB besides (Qt, the driver): 2 x (768 + 200) MB keeps the
// process tree under 2 GB on any machine. Measured: 32 spheres at 1 GB of meshes took 1.15 GB
// resident in --render, 1.24 GB in the window.
constexpr std::uint64_t kMeshBudgetCap = 768ull << 20;
MeshBudget meshBudget(std::uint64_t machineBytes = machineMemoryBytes());

// What `object` will take: its shape at its tessellation, or its mesh file once loaded; with
// flat normals generated every corner may become a vertex of its own (3 per triangle).
MeshCost objectCost(const ObjectSettings &object, const MeshFileSizes &files);
MeshCost sceneCost(const Scene &scene, const MeshFileSizes &files);

struct BudgetFit
{
    MeshCost asked, fitted;
    int tessellation = 0;     // the highest any object has now, where some were lowered
    std::vector<int> lowered; // the objects lowered (indices)
    bool fits = true;         // false: over the budget even at the least tessellation
    // "32 objects at tessellation 2000 would make 128 million triangles (~8.8 GB); ...";
    // empty when nothing was lowered.
    QString message;
};

// Lowers the tessellation of the objects that ask most (all to the highest value that fits)
// when the scene's meshes would take more than `budget`; changes nothing otherwise.
BudgetFit fitToBudget(Scene &scene, const MeshFileSizes &files, const MeshBudget &budget);

// The highest tessellation object `index` may be given, the others as they are, within the
// budget (the Object panel's box); kMaxTessellation when its tessellation does not count (a
// cube, a loaded mesh file), kMinTessellation at the least.
int highestTessellation(const Scene &scene, int index, const MeshFileSizes &files,
                        const MeshBudget &budget);

// "1.5 GB", "340 MB": sizes in messages (binary units).
QString byteSizeText(std::uint64_t bytes);

} // namespace lb
