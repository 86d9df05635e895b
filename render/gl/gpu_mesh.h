#pragma once
// A mesh on the GPU: one buffer per attribute in the fixed slots every program binds
// (program.h), the indices, and two vertex arrays: the triangles, and the normal lines (the
// same position and normal buffers read once per instance). Call with the context current.

#include "gl_object.h"
#include "mesh.h"

#include <QOpenGLExtraFunctions>

#include <array>

namespace lb {

class GpuMesh
{
public:
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
    bool hasVertices() const { return m_vertexCount > 0; }

private:
    GlVertexArray m_triangles, m_normalLines;
    std::array<GlBuffer, 4> m_attributes; // position, normal, colour, texture coordinate
    GlBuffer m_indices;
    GLsizei m_indexCount = 0;
    GLsizei m_vertexCount = 0;
    bool m_colors = false, m_uvs = false; // absent arrays read as white and (0, 0)
};

} // namespace lb
