#pragma once
// Normal generation for meshes that have none, or when the user asks for smooth or flat
// normals: the object panel's "Normals" choice.

#include "mesh.h"

#include <atomic>
#include <optional>

namespace lb {

// A copy of `mesh` whose normals are generated. Each corner of a triangle gets the sum of
// the unit normals of the triangles around its position (vertices at the same position count
// as one, so seams of texture coordinates or colours don't crease), weighted by their angle
// at that position, taking only the triangles whose normal is within `creaseDegrees` of the
// corner's own triangle. 0 gives flat normals, 180 fully smooth ones. A vertex whose corners
// end up with different normals is split. Every index must be below the vertex count.
// Linear in the corners: a position with more than 64 corners (a fan, bad data all at the
// origin) compares bins of about 3 degrees of normals instead of every pair of corners.
// Returns nothing when `cancel` was set. `weld`: weldPositions() of the mesh's positions, when
// the caller has it already (the outward check's), else made here.
std::optional<Mesh> withGeneratedNormals(const Mesh &mesh, float creaseDegrees,
                                         const std::atomic_bool *cancel = nullptr,
                                         const std::vector<std::uint32_t> *weld = nullptr);

} // namespace lb
