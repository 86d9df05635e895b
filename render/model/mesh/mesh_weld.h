#pragma once
// Vertices at the same position, found by hashing: what normal generation and orientation
// treat as one point, whatever texture seams or colours split in the file.

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace lb {

// Index of the first vertex at each vertex's position (exact float equality; -0 equals 0).
std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3> &positions);

// `given` when the caller welded these positions already (one of the right size), else a
// weld made into `own`: one weld per mesh build, shared by the normals and the outward check.
const std::vector<std::uint32_t> &givenOrOwnWeld(const std::vector<glm::vec3> &positions,
                                                 const std::vector<std::uint32_t> *given,
                                                 std::vector<std::uint32_t> &own);

} // namespace lb
