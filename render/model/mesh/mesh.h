#pragma once
// CPU meshes: indexed triangles with per-vertex normals, colours and texture coordinates,
// and the procedural shapes of the object panel.

#include "scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace lb {

struct Mesh
{
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> colors;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices; // three per triangle

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Flat-shaded cube of side 2 (24 vertices: each face has its own normals).
Mesh makeCube();
// Smooth UV sphere of radius 1 with `slices` around Y and `stacks` from pole to pole.
Mesh makeSphere(int slices, int stacks);
// Torus around Y with ring radius `major` and tube radius `minor`.
Mesh makeTorus(int ringSegments, int tubeSegments, float major = 0.7f, float minor = 0.3f);
// Square of side 2 in the XY plane facing +Z, split into divisions x divisions quads.
Mesh makePlane(int divisions);
// The object panel's shape at the given tessellation (the cube ignores it).
Mesh makeShape(Shape shape, int tessellation);
// How many triangles makeShape() makes, without making them.
std::size_t shapeTriangleCount(Shape shape, int tessellation);
// How many vertices makeShape() makes, without making them (the seams and poles repeat theirs).
std::size_t shapeVertexCount(Shape shape, int tessellation);
// Arrow of length 1 from the origin along +Z (shaft and cone), for a directional light.
Mesh makeArrow(int segments);

} // namespace lb
