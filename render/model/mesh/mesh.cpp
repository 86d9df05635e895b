#include "mesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

constexpr float kTwoPi = glm::two_pi<float>();
constexpr float kPi = glm::pi<float>();

// Vertex colours the built-in shapes carry: an RGB cube over the bounding box, so that the
// "vertex colours" switch shows a smooth, recognisable gradient on every shape.
void colourByPosition(Mesh &mesh)
{
    float extent = 1e-6f;
    for (const glm::vec3 &p : mesh.positions)
        extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    mesh.colors.clear();
    mesh.colors.reserve(mesh.positions.size());
    for (const glm::vec3 &p : mesh.positions)
        mesh.colors.push_back(glm::clamp(0.5f + 0.5f * p / extent, 0.0f, 1.0f));
}

// Indices of a (rows+1) x (cols+1) grid of vertices laid out row by row.
void addGridIndices(Mesh &mesh, std::uint32_t first, int rows, int cols)
{
    const std::uint32_t stride = std::uint32_t(cols) + 1;
    mesh.indices.reserve(mesh.indices.size() + 6 * std::size_t(rows) * std::size_t(cols));
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const std::uint32_t a = first + std::uint32_t(r) * stride + std::uint32_t(c);
            const std::uint32_t b = a + stride;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
}

} // namespace

Mesh makeCube()
{
    Mesh mesh;
    // Each face: normal, and two axes spanning it such that u x v = normal (CCW from outside).
    const glm::vec3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto &face : faces) {
        const std::uint32_t first = std::uint32_t(mesh.positions.size());
        for (int j = 0; j <= 1; ++j) {
            for (int i = 0; i <= 1; ++i) {
                const float u = i ? 1.0f : -1.0f;
                const float v = j ? 1.0f : -1.0f;
                mesh.positions.push_back(face[0] + u * face[1] + v * face[2]);
                mesh.normals.push_back(face[0]);
                mesh.uvs.emplace_back(float(i), float(j));
            }
        }
        mesh.indices.insert(mesh.indices.end(),
                            {first, first + 1, first + 3, first, first + 3, first + 2});
    }
    colourByPosition(mesh);
    return mesh;
}

Mesh makeSphere(int slices, int stacks)
{
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    Mesh mesh;
    // Reserved: grown by doubling, a big sphere's arrays held up to twice their size for as
    // long as it is drawn (the scene budget counts them at their size).
    const std::size_t n = std::size_t(slices + 1) * std::size_t(stacks + 1);
    mesh.positions.reserve(n);
    mesh.normals.reserve(n);
    mesh.uvs.reserve(n);
    // Rows run from the north pole down; the seam and the poles repeat vertices so that each
    // has its own texture coordinate. The repeats sit at exactly the same position (sin(pi)
    // is not 0 in floats), so normal generation sees one surface there.
    for (int r = 0; r <= stacks; ++r) {
        const float theta = kPi * float(r) / float(stacks);
        const float ring = r == 0 || r == stacks ? 0.0f : std::sin(theta);
        for (int c = 0; c <= slices; ++c) {
            const float phi = kTwoPi * float(c % slices) / float(slices);
            const glm::vec3 p(ring * std::sin(phi), std::cos(theta), ring * std::cos(phi));
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            mesh.uvs.emplace_back(float(c) / float(slices), 1.0f - float(r) / float(stacks));
        }
    }
    addGridIndices(mesh, 0, stacks, slices);
    colourByPosition(mesh);
    return mesh;
}

Mesh makeTorus(int ringSegments, int tubeSegments, float major, float minor)
{
    ringSegments = std::max(ringSegments, 3);
    tubeSegments = std::max(tubeSegments, 3);
    Mesh mesh;
    const std::size_t n = std::size_t(ringSegments + 1) * std::size_t(tubeSegments + 1);
    mesh.positions.reserve(n);
    mesh.normals.reserve(n);
    mesh.uvs.reserve(n);
    for (int r = 0; r <= ringSegments; ++r) {
        const float u = kTwoPi * float(r % ringSegments) / float(ringSegments); // seams meet
        const glm::vec3 ringDir(std::sin(u), 0.0f, std::cos(u));
        for (int t = 0; t <= tubeSegments; ++t) {
            const float v = kTwoPi * float(t % tubeSegments) / float(tubeSegments);
            const glm::vec3 normal = std::cos(v) * ringDir + glm::vec3(0, std::sin(v), 0);
            mesh.positions.push_back(major * ringDir + minor * normal);
            mesh.normals.push_back(normal);
            mesh.uvs.emplace_back(4.0f * float(r) / float(ringSegments),
                                  float(t) / float(tubeSegments));
        }
    }
    addGridIndices(mesh, 0, ringSegments, tubeSegments);
    colourByPosition(mesh);
    return mesh;
}

Mesh makePlane(int divisions)
{
    divisions = std::max(divisions, 1);
    Mesh mesh;
    const std::size_t n = std::size_t(divisions + 1) * std::size_t(divisions + 1);
    mesh.positions.reserve(n);
    mesh.normals.reserve(n);
    mesh.uvs.reserve(n);
    for (int r = 0; r <= divisions; ++r) {
        const float y = 1.0f - 2.0f * float(r) / float(divisions);
        for (int c = 0; c <= divisions; ++c) {
            const float x = -1.0f + 2.0f * float(c) / float(divisions);
            mesh.positions.emplace_back(x, y, 0.0f);
            mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
            mesh.uvs.emplace_back(0.5f * (x + 1.0f), 0.5f * (y + 1.0f));
        }
    }
    addGridIndices(mesh, 0, divisions, divisions);
    colourByPosition(mesh);
    return mesh;
}

Mesh makeShape(Shape shape, int tessellation)
{
    switch (shape) {
    case Shape::Cube:
        return makeCube();
    case Shape::Sphere:
        return makeSphere(tessellation, std::max(2, tessellation / 2));
    case Shape::Torus:
        return makeTorus(2 * tessellation, tessellation);
    case Shape::Plane:
        return makePlane(tessellation);
    }
    return makeSphere(tessellation, tessellation / 2);
}

std::size_t shapeTriangleCount(Shape shape, int tessellation)
{
    const std::size_t t = std::size_t(std::max(tessellation, 3));
    switch (shape) {
    case Shape::Cube:
        return 12;
    case Shape::Sphere:
        return 2 * t * std::max<std::size_t>(2, t / 2); // the grid's quads, poles included
    case Shape::Torus:
        return 2 * (2 * t) * t;
    case Shape::Plane:
        return 2 * t * t;
    }
    return 0;
}

std::size_t shapeVertexCount(Shape shape, int tessellation)
{
    // As makeShape() and the make functions clamp their arguments.
    const std::size_t t = std::size_t(std::max(tessellation, 3));
    switch (shape) {
    case Shape::Cube:
        return 24;
    case Shape::Sphere:
        return (t + 1) * (std::max<std::size_t>(2, t / 2) + 1);
    case Shape::Torus:
        return (2 * t + 1) * (t + 1);
    case Shape::Plane:
        return (t + 1) * (t + 1);
    }
    return 0;
}

Mesh makeArrow(int segments)
{
    Mesh mesh;
    const float shaftRadius = 0.025f, headRadius = 0.07f, headStart = 0.7f;
    // A ring of `segments` vertices at height z and radius rad.
    auto ring = [&](float z, float rad, float normalZ) {
        for (int i = 0; i <= segments; ++i) {
            const float a = kTwoPi * float(i) / float(segments);
            const glm::vec3 radial(std::cos(a), std::sin(a), 0.0f);
            mesh.positions.push_back(glm::vec3(rad * radial.x, rad * radial.y, z));
            mesh.normals.push_back(glm::normalize(radial + glm::vec3(0, 0, normalZ)));
            mesh.uvs.emplace_back(0.0f, 0.0f);
        }
    };
    std::uint32_t first = 0;
    ring(0.0f, shaftRadius, 0.0f);
    ring(headStart, shaftRadius, 0.0f);
    addGridIndices(mesh, first, 1, segments);
    first = std::uint32_t(mesh.positions.size());
    ring(headStart, headRadius, 0.5f);
    ring(1.0f, 0.0f, 0.5f);
    addGridIndices(mesh, first, 1, segments);
    colourByPosition(mesh);
    return mesh;
}

} // namespace lb
