#pragma once
// Draws a scene into the current framebuffer with the built-in programs. Owns every GPU
// object it creates; call cleanup() with the context current before the context goes away.

#include "checker_texture.h"
#include "frames.h"
#include "mesh.h"
#include "scene.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLVertexArrayObject>
#include <QSize>

#include <array>
#include <memory>

namespace lb {

class Renderer : protected QOpenGLExtraFunctions
{
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer &) = delete;
    Renderer &operator=(const Renderer &) = delete;

    // With a current context: resolves GL functions, builds the programs, makes the texture.
    // Returns an empty string on success, or what went wrong.
    QString initialize();
    void cleanup();
    bool isInitialized() const { return m_initialized; }

    // Draws into the bound framebuffer, which is `pixels` large.
    void render(const Scene &scene, QSize pixels);

    // The CPU mesh of the scene's object, as drawn (built when the shape changes).
    const Mesh &meshFor(const ObjectSettings &object);
    const CheckerTexture &checkerTexture() const { return m_checker; }

private:
    struct GpuMesh
    {
        QOpenGLVertexArrayObject vao;
        std::array<QOpenGLBuffer, 4> attributes;
        QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
        GLsizei indexCount = 0;
    };

    void upload(GpuMesh &gpu, const Mesh &mesh);
    void destroy(GpuMesh &gpu);
    void draw(GpuMesh &gpu);
    void setLightingUniforms(GLuint program, const Scene &scene, const Frames &frames);
    void drawLightMarker(const Scene &scene, const Frames &frames);

    bool m_initialized = false;
    GLuint m_gouraud = 0, m_phong = 0, m_unlit = 0;
    GLuint m_texture = 0;
    CheckerTexture m_checker;

    Mesh m_objectMesh;
    Shape m_objectShape = Shape::Sphere;
    int m_objectTessellation = -1; // -1: no mesh built yet
    bool m_objectUploaded = false;
    GpuMesh m_object, m_markerSphere, m_markerArrow;
};

} // namespace lb
