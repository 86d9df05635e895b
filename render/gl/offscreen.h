#pragma once
// Renders scenes without a window: its own context, an offscreen surface and a framebuffer
// object. Used by the command line (--render, --probe) and the GL tests. Needs a display
// with OpenGL (an X server; Xvfb when headless).

#include "context_loss.h"
#include "mesh_file.h"
#include "object_mesh.h"
#include "program_trial.h"
#include "renderer.h"

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QSize>

#include <memory>
#include <optional>

namespace lb {

// OpenGL 3.3 core with a depth buffer, for every context the process makes. Call before the
// first window or context is created.
void setDefaultGlFormat();

class OffscreenRenderer
{
public:
    ~OffscreenRenderer();
    // Returns an empty string on success, or why there is no OpenGL.
    QString initialize(QSize size);
    QImage render(const Scene &scene);
    // Draws the object with the user's program from now on, if it links (Renderer).
    ProgramBuild useProgram(const QString &vertexSource, const QString &fragmentSource);
    // Draws `frames` frames and waits for the GPU; for the benchmarks.
    void renderFrames(const Scene &scene, int frames);
    // Milliseconds to draw one frame of `scene` at `size` and wait for it, in a framebuffer of
    // its own (a program's trial at a small size).
    double timeFrame(const Scene &scene, QSize size);
    // The user program's trial (program_trial.h) on frames of `scene` drawn here, the
    // built-in program's as the reference.
    TrialResult tryUserProgram(const Scene &scene, const QString &vertex, const QString &fragment,
                               QSize target, double budgetMs, const TrialSizes &sizes);
    Renderer &renderer() { return m_renderer; }
    // Whether the driver reset the context (context_loss.h): nothing drawn since counts.
    bool wasReset();
    // The loaded file the scene's object names (--mesh); nullptr draws the shapes.
    void setMeshFile(std::shared_ptr<const MeshFile> file) { m_file = std::move(file); }
    // The mesh drawn for `scene`, built when the object settings ask for another one. Not
    // after dropCpuMeshes().
    const Mesh &objectMesh(const Scene &scene);
    // For frames that need only pixels from now on (the command line without --probe): the
    // object of `scene` goes to the GPU now, and the file's mesh and the drawn one are let go,
    // so that a big mesh's draw holds one copy of it, the driver's. The frames after draw
    // that object whatever their scene's object settings say.
    void dropCpuMeshes(const Scene &scene);
    std::uint64_t objectTriangleCount() const { return m_renderer.objectTriangleCount(); }
    // Draws this mesh for every scene from now on, whatever its object says (the trial
    // helper is given the window's mesh).
    void setObjectMesh(std::shared_ptr<const Mesh> mesh);

private:
    QOpenGLContext m_context;
    QOffscreenSurface m_surface;
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    Renderer m_renderer;
    QSize m_size;
    std::shared_ptr<const MeshFile> m_file;
    std::optional<ObjectMeshKey> m_key;
    bool m_meshGiven = false;
    bool m_gpuOnly = false; // dropCpuMeshes() was called
    // Builds the object's mesh for `scene` unless it is given or only on the GPU.
    void prepareObject(const Scene &scene);
    // The bound framebuffer's pixels, top row first, in one image.
    QImage readFrame();
    ResetStatus m_resetStatus;
};

} // namespace lb
