#pragma once
// Draws a scene into the current framebuffer with the built-in programs. Owns every GPU
// object it creates; call cleanup() with the context current before the context goes away.

#include "compare.h"
#include "frames.h"
#include "mesh.h"
#include "program.h"
#include "scene.h"
#include "texture.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLVertexArrayObject>
#include <QSize>

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

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

    // Draws into the bound framebuffer, which is `pixels` large: one view, or two sides of
    // a comparison (compare.h) side by side, across a wipe, or as their difference.
    void render(const Scene &scene, QSize pixels);
    // The probe's arrows, drawn over every view (no depth test: they stay visible), and the
    // frame pixel whose colour render() reads back before drawing them (none: x < 0).
    struct Arrow
    {
        glm::vec3 origin, direction, colour; // eye coordinates; the length is the direction's
    };
    void setProbe(std::vector<Arrow> arrows, QPoint framePixel);
    // The colour render() read at the probe's pixel (0-255), if it read one.
    std::optional<glm::ivec3> probedColour() const { return m_probedColour; }

    // What the last difference view measured (valid only after one was drawn).
    const DifferenceStats &difference() const { return m_difference; }

    // Builds a program from the user's sources. When it links it replaces the user program
    // (the object is drawn with it instead of the built-in pair); when it does not, whatever
    // drew before keeps drawing. Returns the build with its diagnostics either way.
    ProgramBuild setUserProgram(const QString &vertexSource, const QString &fragmentSource);
    bool hasUserProgram() const { return m_user.id != 0; }

    // The object's mesh (object_mesh.h builds it) and the texture the texture switch puts on
    // it (nullptr: the checker). Uploaded by the next render(). Without a mesh, render()
    // draws only the background and the light.
    void setObject(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const Texture> texture);
    const Mesh *objectMesh() const { return m_objectMesh.get(); }
    const Texture &texture() const { return m_objectTexture ? *m_objectTexture : m_checker; }

private:
    struct GpuMesh
    {
        QOpenGLVertexArrayObject vao;
        QOpenGLVertexArrayObject normalLines; // positions and normals, one instance each
        std::array<QOpenGLBuffer, 4> attributes;
        QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
        GLsizei indexCount = 0;
        GLsizei vertexCount = 0;
        bool colors = false, uvs = false; // absent arrays read as white and (0, 0)
    };

    void upload(GpuMesh &gpu, const Mesh &mesh);
    void destroy(GpuMesh &gpu);
    void draw(GpuMesh &gpu);
    void drawNormals(const Scene &scene, const Frames &frames);
    GLuint uploadTexture(const QImage &image);
    struct Program
    {
        GLuint id = 0;
        std::vector<ActiveUniform> uniforms;
    };
    Program builtIn(const QString &name, QString &error, const QString &fragment = {});
    void release(Program &program);
    static GLint uniformLocation(const Program &program, const char *name);
    const Program &objectProgram(const Scene &scene) const;
    const Program &builtInProgram(const Scene &scene) const;
    // One side: cleared and drawn in `view` (top-left origin in a frame `frame` high), only
    // inside `clip`.
    void drawView(const Scene &scene, const Program &program, QRect view, QRect clip,
                  int frameHeight);
    void drawDivider(int column, QSize frame);
    void drawProbe(const Scene &scene, QSize pixels);
    void drawDifference(const Scene &scene, QSize pixels);
    void measureDifference(QSize pixels);
    void setUniforms(const Program &program, const Scene &scene, const Frames &frames);
    void setShaderValue(const ActiveUniform &uniform, const Scene &scene);
    // Up to n values into a uniform (an array's first n elements), in its declared type.
    void setVectors(const ActiveUniform &uniform, const glm::vec4 *values, int n);
    void drawLightMarker(const Light &light, const Frames &frames);

    bool m_initialized = false;
    Program m_gouraud, m_phong, m_unlit, m_normals, m_differenceProgram, m_user;
    GLuint m_checkerId = 0, m_objectTextureId = 0;
    Texture m_checker;

    std::shared_ptr<const Mesh> m_objectMesh;
    std::shared_ptr<const Texture> m_objectTexture;
    bool m_objectUploaded = false, m_objectTextureUploaded = true;
    GpuMesh m_object, m_markerSphere, m_markerArrow;
    // The difference view draws each side into its own framebuffer first.
    std::unique_ptr<QOpenGLFramebufferObject> m_sideFbo[2];
    GpuMesh m_screenTriangle; // covers the viewport: the difference pass draws it
    DifferenceStats m_difference;
    std::vector<Arrow> m_probeArrows;
    QPoint m_probePixel{-1, -1};
    std::optional<glm::ivec3> m_probedColour;
};

} // namespace lb
