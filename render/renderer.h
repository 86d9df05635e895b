#pragma once
// Draws a scene into the current framebuffer with the built-in programs. Owns every GPU
// object it creates; call cleanup() with the context current before the context goes away.

#include "checker_texture.h"
#include "frames.h"
#include "glsl/program.h"
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

    // Builds a program from the user's sources. When it links it replaces the user program
    // (the object is drawn with it instead of the built-in pair); when it does not, whatever
    // drew before keeps drawing. Returns the build with its diagnostics either way.
    ProgramBuild setUserProgram(const QString &vertexSource, const QString &fragmentSource);
    bool hasUserProgram() const { return m_user.id != 0; }

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
    struct Program
    {
        GLuint id = 0;
        std::vector<ActiveUniform> uniforms;
    };
    Program builtIn(const QString &name, QString &error);
    void release(Program &program);
    static GLint uniformLocation(const Program &program, const char *name);
    const Program &objectProgram(const Scene &scene) const;
    void setUniforms(const Program &program, const Scene &scene, const Frames &frames);
    void setShaderValue(const ActiveUniform &uniform, const Scene &scene);
    void drawLightMarker(const Scene &scene, const Frames &frames);

    bool m_initialized = false;
    Program m_gouraud, m_phong, m_unlit, m_user;
    GLuint m_texture = 0;
    CheckerTexture m_checker;

    Mesh m_objectMesh;
    Shape m_objectShape = Shape::Sphere;
    int m_objectTessellation = -1; // -1: no mesh built yet
    bool m_objectUploaded = false;
    GpuMesh m_object, m_markerSphere, m_markerArrow;
};

} // namespace lb
