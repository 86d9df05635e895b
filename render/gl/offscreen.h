#pragma once
// Renders scenes without a window: its own context, an offscreen surface and a framebuffer
// object. Used by the command line (--render, --probe) and the GL tests. Needs a display
// with OpenGL (an X server; Xvfb when headless).

#include "context_loss.h"
#include "mesh_file.h"
#include "object_mesh.h"
#include "program_host.h"
#include "program_trial.h"
#include "renderer.h"

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QSize>

#include <map>
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
    // Draws the object with the user's program from now on, if it links and `trial` (when
    // given) does not refuse it (Renderer::setUserProgram).
    ProgramBuild useProgram(const QString &vertexSource, const QString &fragmentSource,
                            const std::function<std::optional<Diagnostic>()> &trial = {},
                            const UniformBindings &bindings = {});
    // Draws `frames` frames and waits for the GPU; for the benchmarks.
    void renderFrames(const Scene &scene, int frames);
    // What one frame of `scene` at `size` costs, waited for, in a framebuffer of its own (a
    // program's trial at a small size): milliseconds as Renderer::renderTimed counts them.
    double timeFrame(const Scene &scene, QSize size);
    // The user program's trial (program_trial.h) on frames of `scene` drawn here, the
    // built-in program's as the reference.
    TrialResult tryUserProgram(const Scene &scene, const QString &vertex, const QString &fragment,
                               QSize target, double budgetMs, const TrialSizes &sizes);
    Renderer &renderer() { return m_renderer; }
    // Whether the driver reset the context (context_loss.h): nothing drawn since counts.
    bool wasReset();
    // A loaded file that the scene's objects may name (by its path); an object naming a
    // file not added here is drawn as its shape.
    void addMeshFile(std::shared_ptr<const MeshFile> file);
    // An image file the scene's objects may name as their texture (ObjectSettings::
    // textureFile); an object naming one not added here shows what it would without it.
    void addTextureFile(const QString &path, std::shared_ptr<const Texture> texture);
    // Reads every image file `scene` names (each once) and adds it; the first that cannot be
    // read stops it: "FILE: why", or empty when all are in.
    QString readTextureFiles(const Scene &scene);
    // The mesh drawn for object `index` of `scene`, built when its settings ask for another
    // one. Not after dropCpuMeshes().
    const Mesh &objectMesh(const Scene &scene, int index = 0);
    // What the Faces choice turned in the meshes of `scene`'s objects, built as objectMesh()
    // builds them: "bunny.ply: faces turned: the file winds them clockwise", one line a file.
    QStringList facesRemarks(const Scene &scene);
    // What the probe needs of every object of `scene` (probe.h), built as objectMesh() builds.
    ProbedObjects probedObjects(const Scene &scene);
    // For frames that need only pixels from now on (the command line without --probe): the
    // objects of `scene` go to the GPU now, and the files' meshes and the drawn ones are let
    // go, so that a big mesh's draw holds one copy of it, the driver's. The frames after draw
    // those objects whatever their scene's object settings say.
    void dropCpuMeshes(const Scene &scene);
    std::uint64_t objectTriangleCount() const { return m_renderer.objectTriangleCount(); }
    // Draws this mesh for the first object of every scene from now on, whatever it says, and
    // no other (the trial helper is given the window's mesh).
    void setObjectMesh(std::shared_ptr<const Mesh> mesh);

private:
    QOpenGLContext m_context;
    QOffscreenSurface m_surface;
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    Renderer m_renderer;
    QSize m_size;
    std::map<QString, std::shared_ptr<const MeshFile>> m_files;   // by path
    std::map<QString, std::shared_ptr<const Texture>> m_textures; // by path
    std::vector<std::optional<ObjectMeshKey>> m_keys;             // by object
    std::vector<QString> m_remarks; // by object: buildObjectMesh's remark
    bool m_meshGiven = false;
    bool m_gpuOnly = false; // dropCpuMeshes() was called
    // Builds the objects' meshes for `scene` unless given or only on the GPU.
    void prepareObjects(const Scene &scene);
    // The bound framebuffer's pixels, top row first, in one image.
    QImage readFrame();
    ResetStatus m_resetStatus;
};

// An offscreen renderer as the host of a program's route (program_route.h): built there, its
// trial frames drawn of `scene`.
class OffscreenProgramHost : public ProgramHost
{
public:
    OffscreenProgramHost(OffscreenRenderer &offscreen, const Scene &scene)
        : m_offscreen(offscreen), m_scene(scene)
    {
    }
    ProgramBuild use(const ProgramSources &sources,
                     const std::function<std::optional<Diagnostic>()> &trial = {}) override
    {
        return m_offscreen.useProgram(sources.vertex, sources.fragment, trial, sources.bindings);
    }
    double timeFrame(QSize pixels) override { return m_offscreen.timeFrame(m_scene, pixels); }
    double timeBuiltInFrame(QSize pixels) override
    {
        return m_offscreen.renderer().withBuiltIn([&] { return timeFrame(pixels); });
    }

private:
    OffscreenRenderer &m_offscreen;
    const Scene &m_scene;
};

} // namespace lb
