#include "gpu_mesh.h"

#include "program.h"

#include <glm/vec4.hpp>

#include <vector>

namespace lb {

namespace {

constexpr int kNormalLineSizes[2] = {3, 4}; // position, normal: floats a vertex

// Batches of a big draw (GpuMesh::draw). Measured on a 1M-triangle torus at 1280x720 with
// llvmpipe on 2 cores (bench/README.md): one draw 12-14.5 fps and 288 MB; batches of 16k
// triangles with 2 in flight 16-21 fps and 195 MB; 8k about the same, 32k 14-20 fps, 219 MB.
constexpr std::uint64_t kTrianglesPerBatch = 16384;
constexpr std::size_t kBatchesInFlight = 2;
// A batch that takes longer than this (a slow program on a big mesh) is not waited for
// further: the next one is queued, as without batches.
constexpr GLuint64 kFenceWaitNs = 1'000'000'000;

// Fills the bound array buffer (`bytes` long, made by glBufferData) with `normals`, w = 0.
void writeNormals(QOpenGLExtraFunctions &gl, const std::vector<glm::vec3> &normals,
                  GLsizeiptr bytes)
{
    auto *out = static_cast<glm::vec4 *>(gl.glMapBufferRange(
        GL_ARRAY_BUFFER, 0, bytes, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
    if (out) {
        for (const glm::vec3 &normal : normals)
            *out++ = glm::vec4(normal, 0.0f);
        if (gl.glUnmapBuffer(GL_ARRAY_BUFFER))
            return;
    }
    // No mapping (or the driver lost what was written): through a padded copy after all.
    std::vector<glm::vec4> padded;
    padded.reserve(normals.size());
    for (const glm::vec3 &normal : normals)
        padded.emplace_back(normal, 0.0f);
    gl.glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, padded.data());
}

} // namespace

std::vector<DrawRange> drawRanges(std::uint64_t total, std::uint64_t most, std::uint64_t unit)
{
    std::vector<DrawRange> ranges;
    forEachDrawRange(total, most, unit, [&](DrawRange r) { ranges.push_back(r); });
    return ranges;
}

void GpuMesh::upload(QOpenGLExtraFunctions &gl, const Mesh &mesh)
{
    // Positions go up as vec3 and GL supplies w = 1. Normals go up with w = 0, so a shader
    // that declares vNormal as vec4 (the slides do) reads a direction; they are written
    // straight into the mapped buffer (no padded CPU copy: 8 MB for a 1M-triangle mesh).
    const std::size_t n = mesh.vertexCount();
    m_colors = mesh.colors.size() == n;
    m_uvs = mesh.uvs.size() == n;
    m_vertexCount = n;
    const void *data[4] = {mesh.positions.data(), nullptr, mesh.colors.data(), mesh.uvs.data()};
    const bool present[4] = {true, mesh.normals.size() == n, m_colors, m_uvs};
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
        if (i == 1 && present[i] && bytes > 0)
            writeNormals(gl, mesh.normals, bytes);
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
    // Big meshes go in batches with a fence after each, and at most kBatchesInFlight of them
    // queued: llvmpipe keeps each queued batch's binned triangles until it is drawn (36 MB
    // blocks, ~130 MB for one 1M-triangle draw), and smaller batches keep both of its
    // threads busy. A glFlush does not bound the queue; waiting for a batch two back does.
    std::array<GLsync, kBatchesInFlight> fences{};
    std::size_t batch = 0;
    forEachDrawRange(
        m_indexCount, std::min(m_maxPerDraw, 3 * kTrianglesPerBatch), 3, [&](DrawRange r) {
            GLsync &fence = fences[batch++ % kBatchesInFlight];
            if (fence) {
                gl.glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, kFenceWaitNs);
                gl.glDeleteSync(fence);
            }
            gl.glDrawElements(GL_TRIANGLES, r.count, GL_UNSIGNED_INT,
                              reinterpret_cast<const void *>(r.first * sizeof(std::uint32_t)));
            fence = r.first + std::uint64_t(r.count) < m_indexCount
                        ? gl.glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)
                        : nullptr;
        });
    for (GLsync fence : fences)
        if (fence)
            gl.glDeleteSync(fence);
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
