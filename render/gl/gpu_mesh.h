#pragma once
// A mesh on the GPU: one buffer per attribute in the fixed slots every program binds
// (program.h), the indices, and two vertex arrays: the triangles, and the normal lines (the
// same position and normal buffers read once per instance). Call with the context current.

#include "gl_object.h"
#include "mesh.h"

#include <QOpenGLExtraFunctions>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace lb {

// A piece of a draw: GL counts are GLsizei (int), and a mesh may hold up to 2^32 indices.
struct DrawRange
{
    std::uint64_t first = 0;
    GLsizei count = 0;
};
// `total` items in pieces of at most `most` (a multiple of `unit`, rounded down, at least one
// unit, at most GpuMesh::kMaxPerDraw), in order; `draw(range)` for each, allocating nothing.
template <typename F>
void forEachDrawRange(std::uint64_t total, std::uint64_t most, std::uint64_t unit, F &&draw);
std::vector<DrawRange> drawRanges(std::uint64_t total, std::uint64_t most, std::uint64_t unit);

class GpuMesh
{
public:
    // The most indices (and normal lines) one draw call takes; more are drawn in several calls.
    static constexpr std::uint64_t kMaxPerDraw =
        0x7ffffffe; // the largest multiple of 3 in a GLsizei

    // Replaces what the buffers hold with `mesh` (objects are made on the first upload).
    void upload(QOpenGLExtraFunctions &gl, const Mesh &mesh);
    // Deletes the GL objects; call with the context current.
    void release();

    // Draws the triangles with the bound program. Arrays the mesh lacks read as white
    // colours and (0, 0) texture coordinates, as the reference (probe.cpp) reads them.
    void draw(QOpenGLExtraFunctions &gl) const;
    // One GL_LINES pair per vertex, instanced: the normals program draws them.
    void drawNormalLines(QOpenGLExtraFunctions &gl) const;

    bool hasTriangles() const { return m_indexCount > 0; }
    std::uint64_t triangleCount() const { return m_indexCount / 3; }
    bool hasVertices() const { return m_vertexCount > 0; }
    // Fewer per call than GL allows: the same pixels, in more calls (tests draw big meshes'
    // pieces with small ones this way).
    void setMaxPerDraw(std::uint64_t most) { m_maxPerDraw = most; }

private:
    // Points the normal lines' position and normal arrays at vertex `first`.
    void pointNormalLinesAt(QOpenGLExtraFunctions &gl, std::uint64_t first) const;

    GlVertexArray m_triangles, m_normalLines;
    std::array<GlBuffer, 4> m_attributes; // position, normal, colour, texture coordinate
    GlBuffer m_indices;
    std::uint64_t m_indexCount = 0;
    std::uint64_t m_vertexCount = 0;
    std::uint64_t m_maxPerDraw = kMaxPerDraw;
    bool m_colors = false, m_uvs = false; // absent arrays read as white and (0, 0)
};

template <typename F>
void forEachDrawRange(std::uint64_t total, std::uint64_t most, std::uint64_t unit, F &&draw)
{
    most = std::max(unit, std::min(most, GpuMesh::kMaxPerDraw) / unit * unit);
    for (std::uint64_t first = 0; first < total; first += most)
        draw(DrawRange{first, GLsizei(std::min(most, total - first))});
}

} // namespace lb
