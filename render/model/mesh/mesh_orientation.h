#pragma once
// Which way a mesh's faces look, and the mesh turned the way the object panel's "Faces"
// choice asks: outward, as in the file, flipped, or two-sided (scene.h's Faces).

#include "mesh.h"

#include <QString>

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

namespace lb {

// What the outward check found. A part is a set of triangles joined through shared
// positions (welded: a texture seam does not split a part). A part encloses a volume when
// its net area (the sum of its triangles' area vectors, zero for a closed surface) is at most
// a tenth of its area, as for a scan with a few holes; its signed volume then says which way
// it is wound. Parts that enclose nothing (a sheet, a single triangle, a bowl) are left as
// they are.
struct OrientationCheck
{
    std::size_t parts = 0;          // parts with triangles
    std::size_t enclosing = 0;      // parts that enclose a volume
    std::size_t turnedFaces = 0;    // enclosing parts wound inwards: their winding turned
    std::size_t turnedNormals = 0;  // enclosing parts whose normals point inwards after that
    std::vector<std::uint8_t> part; // per triangle: kTurnFaces | kTurnNormals; empty: none
    static constexpr std::uint8_t kTurnFaces = 1, kTurnNormals = 2;
    bool changes() const { return turnedFaces > 0 || turnedNormals > 0; }
};

// Looks at `mesh` (its normals too, when it has them); nothing when `cancel` was set.
// Linear in the triangles; the sums run on the machine's cores for big meshes. `weld`:
// weldPositions() of the mesh's positions when the caller has it (normal generation takes
// the same), else made here.
std::optional<OrientationCheck> checkOrientation(const Mesh &mesh,
                                                 const std::atomic_bool *cancel = nullptr,
                                                 const std::vector<std::uint32_t> *weld = nullptr);

// `mesh` with what `check` found turned: the winding of the triangles marked kTurnFaces
// reversed, the normals of those marked kTurnNormals negated.
Mesh orientedMesh(const Mesh &mesh, const OrientationCheck &check);
// Every triangle's winding reversed and every normal negated.
Mesh flippedMesh(const Mesh &mesh);
// `mesh`, then a reversed copy of every triangle with its normals negated: with back faces
// culled, each side of a face is drawn and lit with the normal facing the viewer.
Mesh twoSidedMesh(const Mesh &mesh);

// For the status line and stderr: "faces turned: the file winds them clockwise" and the
// like, or empty when `check` changed nothing.
QString orientationRemark(const OrientationCheck &check);

} // namespace lb
