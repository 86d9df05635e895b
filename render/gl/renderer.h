#pragma once
// Draws a scene into the current framebuffer: the object with the user's program or the
// built-in pair, compare views (two sides, a wipe, or their difference), the overlays and the
// probe's read-back. Owns every GPU object it creates (gl_object.h); call cleanup() with the
// context current before the context goes away.

#include "compare.h"
#include "frame_look.h"
#include "gpu_mesh.h"
#include "overlays.h"
#include "probe.h"
#include "program.h"
#include "scene.h"
#include "texture.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QSize>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <utility>
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
    // The same, waited for (a program's trial): what the frame cost in milliseconds. Where a
    // software rasterizer draws (llvmpipe: on this process's threads), the processor time they
    // used, which other programs busy on the same cores do not stretch as they stretch the
    // wall clock (a slow submission refused under load, issue 47); elsewhere the wall clock.
    double renderTimed(const Scene &scene, QSize pixels);
    // The probe's arrows, drawn over every view (no depth test: they stay visible), and the
    // frame pixel whose colour render() reads back (none: x < 0): the surface's, read before
    // the light markers, normal lines and arrows are drawn over it.
    using Arrow = ProbeArrow;
    void setProbe(std::vector<Arrow> arrows, QPoint framePixel);
    // The colour render() read at the probe's pixel (0-255), if it read one.
    std::optional<glm::ivec3> probedColour() const { return m_probedColour; }
    // Where side B is a program (an exercise's reference, files), render() also draws it over
    // side A's view at the probe's pixel: what the reference draws at the point probed on
    // side A, to compare like with like.
    void setProbeAgainstSideB(bool on) { m_probeAgainstSideB = on; }
    std::optional<glm::ivec3> probedSideBColour() const { return m_probedSideB; }

    // The next render() that draws the user's program alone (no compare view) looks at its
    // frame before any overlay, once: frameLook() then says whether it shows anything.
    void lookAtNextFrame() { m_lookPending = true; }
    std::optional<FrameLook> takeFrameLook() { return std::exchange(m_frameLook, std::nullopt); }

    // What the last difference view measured (valid only after one was drawn), with this
    // tolerance for its share within (an open exercise's, as Check My Work counts).
    const DifferenceStats &difference() const { return m_difference; }
    void setDifferenceTolerance(int tolerance) { m_differenceTolerance = tolerance; }
    // The UI scale the difference view's colour scale is drawn for (differenceScaleBar).
    void setUiScale(double scale) { m_uiScale = scale; }
    // The probe's arrows thin and see-through, so the surface under them stays visible.
    void setProbeArrowsFaded(bool faded) { m_probeArrowsFaded = faded; }
    bool probeArrowsFaded() const { return m_probeArrowsFaded; }

    // Builds a program from the user's sources. When it links it replaces the user program
    // (the object is drawn with it instead of the built-in pair); when it does not, whatever
    // drew before keeps drawing. Returns what the build said either way; the program itself
    // stays here.
    // `trial`, when given, runs once the new program links and draws in its place (render()
    // uses it); a diagnostic it returns refuses the program: the previous one comes back and
    // the build reports the diagnostic as not linked.
    // `bindings`: the user's choice of what feeds which uniform (bindings.h).
    ProgramBuild setUserProgram(const QString &vertexSource, const QString &fragmentSource,
                                const UniformBindings &bindings = {},
                                const std::function<std::optional<Diagnostic>()> &trial = {});
    bool hasUserProgram() const { return bool(m_user.program); }
    // A program built aside, not drawn until it is adopted (while it is tried elsewhere); a
    // new candidate replaces the one before.
    ProgramBuild buildCandidate(const QString &vertexSource, const QString &fragmentSource,
                                const UniformBindings &bindings = {});
    bool hasCandidate() const { return bool(m_candidate.program); }
    void adoptCandidate();
    void dropCandidate() { m_candidate = {}; }
    // Draws the candidate into the bound framebuffer with the rasterizer discarding every
    // primitive: its vertex stage runs, its fragment stage never does, and a driver that
    // generates code at the first draw (llvmpipe) does so now, while the candidate is tried
    // elsewhere, instead of in the first frame after it.
    void prepareCandidate(const Scene &scene, QSize pixels);
    void clearUserProgram() { m_user = {}; } // the built-in programs draw again
    // Side B of the compare views draws this program instead of the built-in one (an
    // exercise's reference) when it links; what the build said either way.
    ProgramBuild setSideBProgram(const QString &vertexSource, const QString &fragmentSource);
    void clearSideBProgram() { m_sideB = {}; }
    bool hasSideBProgram() const { return bool(m_sideB.program); }
    // Runs `f` while the built-in programs draw in the user program's place (a trial's
    // reference), then puts the user program back.
    template <typename F> auto withBuiltIn(F &&f)
    {
        BuiltProgram user = std::move(m_user);
        m_user = {};
        auto result = f();
        m_user = std::move(user);
        return result;
    }

    // What object `index` of the scene is drawn with: its mesh (object_mesh.h builds it) and
    // the texture its texture switch puts on it (nullptr: the checker). Uploaded by the next
    // render(). An object without a mesh (loading, or index beyond those set) is not drawn.
    void setObject(int index, std::shared_ptr<const Mesh> mesh,
                   std::shared_ptr<const Texture> texture);
    // Objects from `count` on are let go (the scene has fewer).
    void setObjectCount(int count);
    int objectCount() const { return int(m_objects.size()); }
    const Mesh *objectMesh(int index = 0) const;
    const std::shared_ptr<const Mesh> &sharedObjectMesh(int index = 0) const;
    const Texture &texture(int index = 0) const;
    // The texture set for object `index` (nullptr: the checker, or no such object).
    const Texture *ownTexture(int index) const;
    // What the probe needs of each object (probe.h); valid until the next setObject().
    ProbedObjects probedObjects() const;
    // Uploads the objects now and lets go of their CPU meshes (objectMesh() is nullptr
    // after; the frames draw what was uploaded): frames that need only pixels keep one copy
    // of a big mesh, the driver's.
    void uploadObjectsAndDropMeshes();
    std::uint64_t objectTriangleCount() const; // all objects' together
    // The most indices one draw call of an object takes (GpuMesh::setMaxPerDraw).
    void setMaxPerDraw(std::uint64_t most);

private:
    // GL counts rows from the bottom; `rect` has its origin top-left in a frame `height` high.
    void setViewportRect(QRect rect, int height);
    const BuiltProgram &objectProgram(const Scene &scene);
    const BuiltProgram &sideBProgram(const Scene &sceneB);
    // The built-in program of the scene's shading, compiled for the lights the scene uses
    // (built once per shading and count, then kept).
    const BuiltProgram &builtInProgram(const Scene &scene);
    const BuiltProgram &specialisedBuiltIn(const BuiltInVariant &variant);
    void uploadObjects();
    // The objects of `scene`, each with its own matrices, material and texture.
    void drawObjects(const Scene &scene, const BuiltProgram &program, float aspect);
    void drawNormalLines(const Scene &scene, float aspect); // the objects' that show them
    bool drawsEveryVisibleObject(const Scene &scene) const;
    glm::ivec3 readPixel(QPoint framePixel, int frameHeight);
    void readSideBAtProbe(const Scene &scene, QSize pixels);
    // One side: cleared and drawn in `view` (top-left origin in a frame `frameHeight` high),
    // only inside `clip`.
    void drawView(const Scene &scene, const BuiltProgram &program, QRect view, QRect clip,
                  int frameHeight);
    void drawSides(const Scene &scene, QSize pixels);
    void drawDivider(int column, QSize frame);
    void drawProbe(const Scene &scene, QSize pixels);
    void drawDifference(const Scene &scene, QSize pixels);
    void measureDifference(QSize pixels);

    bool m_initialized = false;
    bool m_timesProcessor = false; // renderTimed() counts processor time
    // The built-in programs, by variant (builtInProgram), built when first needed.
    std::map<BuiltInVariant, BuiltProgram> m_builtIns;
    BuiltProgram m_differenceProgram, m_user, m_candidate, m_sideB;
    Overlays m_overlays;
    Texture m_checker;
    GlTexture m_checkerTexture;

    struct GpuObject
    {
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const Texture> texture;
        bool uploaded = false, textureUploaded = true;
        GpuMesh gpu;
        // Shared by the objects showing one image (a class's 32 duplicates of a 4096 x 4096
        // photo hold one GPU copy, not 32).
        std::shared_ptr<GlTexture> textureGl;
    };
    std::vector<std::unique_ptr<GpuObject>> m_objects; // by index into Scene::objects
    std::uint64_t m_maxPerDraw = GpuMesh::kMaxPerDraw;
    // The difference view draws each side into its own framebuffer first.
    std::unique_ptr<QOpenGLFramebufferObject> m_sideFbo[2];
    GpuMesh m_screenTriangle; // covers the viewport: the difference pass draws it
    DifferenceStats m_difference;
    int m_differenceTolerance = 2;
    double m_uiScale = 1.0;
    bool m_probeArrowsFaded = false;
    std::vector<Arrow> m_probeArrows;
    QPoint m_probePixel{-1, -1};
    bool m_readingProbe = false; // while render() draws the views the user sees
    bool m_lookPending = false;
    std::optional<FrameLook> m_frameLook;
    bool m_probeAgainstSideB = false;
    std::optional<glm::ivec3> m_probedColour, m_probedSideB;
    std::unique_ptr<QOpenGLFramebufferObject> m_probeFbo; // side B at the probe's pixel
};

} // namespace lb
