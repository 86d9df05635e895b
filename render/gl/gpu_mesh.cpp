#include "gpu_mesh.h"

#include "program.h"

#include <vector>

namespace lb {

namespace {

constexpr int kNormalLineSizes[2] = {3, 4}; // position, normal: floats a vertex

} // namespace

std::vector<DrawRange> drawRanges(std::uint64_t total, std::uint64_t most, std::uint64_t unit)
{
    std::vector<DrawRange> ranges;
    forEachDrawRange(total, most, unit, [&](DrawRange r) { ranges.push_back(r); });
    return ranges;
}

void GpuMesh::upload(QOpenGLExtraFunctions &gl, const Mesh &mesh)
{
    // Normals go up with w = 0, so a shader that declares vNormal as vec4 (the slides do)
    // reads a direction; positions go up as vec3 and GL supplies w = 1.
    std::vector<glm::vec4> normals;
    normals.reserve(mesh.normals.size());
    for (const glm::vec3 &n : mesh.normals)
        normals.emplace_back(n, 0.0f);
    const std::size_t n = mesh.vertexCount();
    m_colors = mesh.colors.size() == n;
    m_uvs = mesh.uvs.size() == n;
    m_vertexCount = n;
    const void *data[4] = {mesh.positions.data(), normals.data(), mesh.colors.data(),
                           mesh.uvs.data()};
    const bool present[4] = {true, normals.size() == n, m_colors, m_uvs};
    const int sizes[4] = {kNormalLineSizes[0], kNormalLineSizes[1], 3, 2};
    const GLuint locations[4] = {kPositionSlot, kNormalSlot, kColorSlot, kTexCoordSlot};
    for (GlVertexArray *vao : {&m_triangles, &m_normalLines})
        if (!*vao)
            *vao = GlVertexArray::create();
    for (std::size_t i = 0; i < 4; ++i) {
        GlBuffer &buffer = m_attributes[i];
        if (!buffer)
            buffer = GlBuffer::create();
        gl.glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
        const GLsizeiptr bytes =
            present[i] ? GLsizeiptr(n * std::size_t(sizes[i]) * sizeof(float)) : 0;
        gl.glBufferData(GL_ARRAY_BUFFER, bytes, present[i] ? data[i] : nullptr, GL_STATIC_DRAW);
        gl.glBindVertexArray(m_triangles.id());
        if (present[i]) {
            gl.glEnableVertexAttribArray(locations[i]);
            gl.glVertexAttribPointer(locations[i], sizes[i], GL_FLOAT, GL_FALSE, 0, nullptr);
        } else {
            gl.glDisableVertexAttribArray(locations[i]);
        }
        if (i < 2) { // the normal lines read positions and normals once per line
            gl.glBindVertexArray(m_normalLines.id());
            gl.glEnableVertexAttribArray(locations[i]);
            gl.glVertexAttribPointer(locations[i], sizes[i], GL_FLOAT, GL_FALSE, 0, nullptr);
            gl.glVertexAttribDivisor(locations[i], 1);
        }
    }
    gl.glBindVertexArray(m_triangles.id());
    if (!m_indices)
        m_indices = GlBuffer::create();
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                    GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                    GL_STATIC_DRAW);
    m_indexCount = mesh.indices.size();
    gl.glBindVertexArray(0);
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuMesh::release()
{
    for (GlBuffer &b : m_attributes)
        b.reset();
    m_indices.reset();
    m_triangles.reset();
    m_normalLines.reset();
    m_indexCount = m_vertexCount = 0;
}

void GpuMesh::draw(QOpenGLExtraFunctions &gl) const
{
    if (!hasTriangles())
        return;
    if (!m_colors)
        gl.glVertexAttrib4f(kColorSlot, 1.0f, 1.0f, 1.0f, 1.0f);
    if (!m_uvs)
        gl.glVertexAttrib4f(kTexCoordSlot, 0.0f, 0.0f, 0.0f, 1.0f);
    gl.glBindVertexArray(m_triangles.id());
    forEachDrawRange(m_indexCount, m_maxPerDraw, 3, [&](DrawRange r) {
        gl.glDrawElements(GL_TRIANGLES, r.count, GL_UNSIGNED_INT,
                          reinterpret_cast<const void *>(r.first * sizeof(std::uint32_t)));
    });
    gl.glBindVertexArray(0);
}

void GpuMesh::drawNormalLines(QOpenGLExtraFunctions &gl) const
{
    if (!hasVertices())
        return;
    gl.glBindVertexArray(m_normalLines.id());
    const bool pieces = m_vertexCount > m_maxPerDraw || m_vertexCount > kMaxPerDraw;
    forEachDrawRange(m_vertexCount, m_maxPerDraw, 1, [&](DrawRange r) {
        if (pieces) // instances count from 0: the arrays start at the piece
            pointNormalLinesAt(gl, r.first);
        gl.glDrawArraysInstanced(GL_LINES, 0, 2, r.count);
    });
    if (pieces)
        pointNormalLinesAt(gl, 0);
    gl.glBindVertexArray(0);
}

void GpuMesh::pointNormalLinesAt(QOpenGLExtraFunctions &gl, std::uint64_t first) const
{
    const GLuint locations[2] = {kPositionSlot, kNormalSlot};
    for (std::size_t i = 0; i < 2; ++i) {
        gl.glBindBuffer(GL_ARRAY_BUFFER, m_attributes[i].id());
        const std::uint64_t offset = first * std::uint64_t(kNormalLineSizes[i]) * sizeof(float);
        gl.glVertexAttribPointer(locations[i], kNormalLineSizes[i], GL_FLOAT, GL_FALSE, 0,
                                 reinterpret_cast<const void *>(offset));
    }
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
}

} // namespace lb
