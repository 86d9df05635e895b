#include "renderer.h"

#include "frames.h"
#include "gpu_texture.h"
#include "process_time.h"
#include "uniform_upload.h"
#include "webgl1_translation.h"

#include <QElapsedTimer>

#include <algorithm>

namespace lb {

namespace {
// Mesa's software rasterizers (llvmpipe, softpipe, swrast) and Google's SwiftShader name
// themselves so in GL_RENDERER.
bool drawsOnProcessor(const char *renderer)
{
    const QByteArray name = QByteArray(renderer ? renderer : "").toLower();
    for (const char *word : {"llvmpipe", "softpipe", "swrast", "software", "swiftshader"})
        if (name.contains(word))
            return true;
    return false;
}
} // namespace

void Renderer::setViewportRect(QRect rect, int height)
{
    glViewport(rect.x(), height - rect.y() - rect.height(), rect.width(), rect.height());
}

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

QString Renderer::initialize()
{
    initializeOpenGLFunctions();
    noteDriverRefusesVersion100(!acceptsVersion100(*this));
    QString error;
    for (bool gouraud : {true, false}) // the default scene's: one light
        m_builtIns[BuiltInVariant{gouraud}] = buildSpecialisedBuiltIn(*this, {gouraud}, error);
    m_differenceProgram = buildBuiltIn(*this, "difference", error);
    error += m_overlays.initialize(*this);
    if (!error.isEmpty())
        return error;

    m_checkerTexture = uploadTexture(*this, m_checker);
    Mesh screen;
    screen.positions = {{-1.0f, -1.0f, 0.0f}, {3.0f, -1.0f, 0.0f}, {-1.0f, 3.0f, 0.0f}};
    screen.indices = {0, 1, 2};
    m_screenTriangle.upload(*this, screen);
    m_timesProcessor = drawsOnProcessor(reinterpret_cast<const char *>(glGetString(GL_RENDERER))) &&
                       processorTimeMs() >= 0.0;
    m_initialized = true;
    return {};
}

double Renderer::renderTimed(const Scene &scene, QSize pixels)
{
    QElapsedTimer wall;
    wall.start();
    const double processorStart = m_timesProcessor ? processorTimeMs() : 0.0;
    render(scene, pixels);
    glFinish();
    return m_timesProcessor ? processorTimeMs() - processorStart
                            : double(wall.nsecsElapsed()) * 1e-6;
}

void Renderer::cleanup()
{
    if (!m_initialized)
        return;
    for (const std::unique_ptr<GpuObject> &o : m_objects) {
        o->gpu.release();
        o->textureGl.reset();
        o->uploaded = false;
        o->textureUploaded = !o->texture;
    }
    m_screenTriangle.release();
    m_overlays.release();
    m_sideFbo[0].reset();
    m_sideFbo[1].reset();
    for (BuiltProgram *p : {&m_differenceProgram, &m_user, &m_candidate, &m_sideB})
        *p = {};
    m_builtIns.clear();
    m_checkerTexture.reset();
    m_initialized = false;
}

ProgramBuild Renderer::setUserProgram(const QString &vertexSource, const QString &fragmentSource,
                                      const UniformBindings &bindings,
                                      const std::function<std::optional<Diagnostic>()> &trial)
{
    BuiltProgram built = buildProgram(*this, vertexSource, fragmentSource, bindings);
    ProgramBuild report = built.build;
    if (!report.ok())
        return report;
    built.shippedBuiltIn = shippedBuiltIn(vertexSource, fragmentSource);
    std::swap(m_user, built); // `built` holds the previous program now
    if (trial)
        if (const std::optional<Diagnostic> refusal = trial()) {
            std::swap(m_user, built);
            report.linked = false;
            report.diagnostics.push_back(*refusal);
        }
    return report;
}

ProgramBuild Renderer::buildCandidate(const QString &vertexSource, const QString &fragmentSource,
                                      const UniformBindings &bindings)
{
    m_candidate = buildProgram(*this, vertexSource, fragmentSource, bindings);
    m_candidate.shippedBuiltIn = shippedBuiltIn(vertexSource, fragmentSource);
    if (!m_candidate.build.ok()) {
        const ProgramBuild report = m_candidate.build;
        m_candidate = {};
        return report;
    }
    return m_candidate.build;
}

void Renderer::adoptCandidate()
{
    m_user = std::move(m_candidate);
    m_candidate = {};
}

void Renderer::prepareCandidate(const Scene &scene, QSize pixels)
{
    if (!m_initialized || !m_candidate.program || pixels.isEmpty())
        return;
    uploadObjects();
    const QRect whole(QPoint(0, 0), pixels);
    glEnable(GL_RASTERIZER_DISCARD);
    drawView(scene, m_candidate, whole, whole, pixels.height());
    glDisable(GL_RASTERIZER_DISCARD);
}

ProgramBuild Renderer::setSideBProgram(const QString &vertexSource, const QString &fragmentSource)
{
    BuiltProgram built = buildProgram(*this, vertexSource, fragmentSource);
    if (built.build.ok())
        m_sideB = std::move(built);
    return built.build.ok() ? m_sideB.build : built.build;
}

const BuiltProgram &Renderer::sideBProgram(const Scene &sceneB)
{
    return m_sideB.program ? m_sideB : builtInProgram(sceneB);
}

const BuiltProgram &Renderer::objectProgram(const Scene &scene)
{
    if (!m_user.program)
        return builtInProgram(scene);
    // The editor's program is the built-in text as shipped: the same program, compiled for
    // the lights the scene uses.
    if (m_user.shippedBuiltIn)
        return specialisedBuiltIn(builtInVariant(scene, *m_user.shippedBuiltIn));
    return m_user;
}

const BuiltProgram &Renderer::builtInProgram(const Scene &scene)
{
    return specialisedBuiltIn(builtInVariant(scene, perVertex(scene.shading.shading)));
}

const BuiltProgram &Renderer::specialisedBuiltIn(const BuiltInVariant &variant)
{
    BuiltProgram &p = m_builtIns[variant];
    if (!p.program) {
        QString error;
        p = buildSpecialisedBuiltIn(*this, variant, error);
        if (!error.isEmpty()) { // the sources differ by three numbers from those built at start
            qWarning("lightbench: %s", qPrintable(error));
            return m_builtIns[BuiltInVariant{variant.gouraud}];
        }
    }
    return p;
}

void Renderer::setObject(int index, std::shared_ptr<const Mesh> mesh,
                         std::shared_ptr<const Texture> texture)
{
    if (index < 0 || index >= kMaxObjects)
        return;
    if (index >= int(m_objects.size()))
        setObjectCount(index + 1);
    GpuObject &o = *m_objects[std::size_t(index)];
    if (mesh != o.mesh)
        o.uploaded = false;
    o.mesh = std::move(mesh);
    if (texture != o.texture)
        o.textureUploaded = false;
    o.texture = std::move(texture);
}

void Renderer::setObjectCount(int count)
{
    count = std::clamp(count, 0, kMaxObjects);
    // Let go with the context current when there is one; GL objects of a lost context are
    // gone anyway (cleanup() released them).
    while (int(m_objects.size()) > count) {
        if (m_initialized) {
            m_objects.back()->gpu.release();
            m_objects.back()->textureGl.reset();
        }
        m_objects.pop_back();
    }
    while (int(m_objects.size()) < count) {
        m_objects.push_back(std::make_unique<GpuObject>());
        m_objects.back()->gpu.setMaxPerDraw(m_maxPerDraw);
    }
}

const Mesh *Renderer::objectMesh(int index) const
{
    return index >= 0 && index < int(m_objects.size()) ? m_objects[std::size_t(index)]->mesh.get()
                                                       : nullptr;
}

const std::shared_ptr<const Mesh> &Renderer::sharedObjectMesh(int index) const
{
    static const std::shared_ptr<const Mesh> none;
    return index >= 0 && index < int(m_objects.size()) ? m_objects[std::size_t(index)]->mesh : none;
}

const Texture *Renderer::ownTexture(int index) const
{
    return index >= 0 && index < int(m_objects.size())
               ? m_objects[std::size_t(index)]->texture.get()
               : nullptr;
}

const Texture &Renderer::texture(int index) const
{
    const bool own =
        index >= 0 && index < int(m_objects.size()) && m_objects[std::size_t(index)]->texture;
    return own ? *m_objects[std::size_t(index)]->texture : m_checker;
}

ProbedObjects Renderer::probedObjects() const
{
    ProbedObjects objects;
    for (int i = 0; i < int(m_objects.size()); ++i)
        objects.push_back({objectMesh(i), &texture(i)});
    return objects;
}

std::uint64_t Renderer::objectTriangleCount() const
{
    std::uint64_t n = 0;
    for (const std::unique_ptr<GpuObject> &o : m_objects)
        n += o->gpu.triangleCount();
    return n;
}

void Renderer::setMaxPerDraw(std::uint64_t most)
{
    m_maxPerDraw = most;
    for (const std::unique_ptr<GpuObject> &o : m_objects)
        o->gpu.setMaxPerDraw(most);
}

void Renderer::uploadObjects()
{
    for (const std::unique_ptr<GpuObject> &o : m_objects) {
        if (!o->uploaded) {
            if (o->mesh)
                o->gpu.upload(*this, *o->mesh);
            else
                o->gpu.release();
            o->uploaded = true;
        }
        if (!o->textureUploaded) {
            o->textureGl.reset();
            for (const std::unique_ptr<GpuObject> &other : m_objects)
                if (other != o && other->texture == o->texture && other->textureUploaded &&
                    other->textureGl)
                    o->textureGl = other->textureGl;
            if (o->texture && !o->textureGl)
                o->textureGl = std::make_shared<GlTexture>(uploadTexture(*this, *o->texture));
            o->textureUploaded = true;
        }
    }
}

void Renderer::uploadObjectsAndDropMeshes()
{
    uploadObjects();
    for (const std::unique_ptr<GpuObject> &o : m_objects)
        o->mesh.reset();
}

void Renderer::render(const Scene &scene, QSize pixels)
{
    if (!m_initialized || pixels.isEmpty())
        return;
    uploadObjects();
    const QRect whole(QPoint(0, 0), pixels);
    glEnable(GL_SCISSOR_TEST);
    m_probedColour.reset();
    m_probedSideB.reset();
    // The probe's pixel is read in the view that holds it, once its surfaces are drawn and
    // before any overlay: a marker, a normal line or an arrow over the point is not the
    // surface. (The difference view's sides are no picture of a surface at that pixel.)
    m_readingProbe = scene.compare.mode != CompareMode::Difference;
    if (scene.compare.mode == CompareMode::Off)
        drawView(scene, objectProgram(scene), whole, whole, pixels.height());
    else if (scene.compare.mode == CompareMode::Difference)
        drawDifference(scene, pixels);
    else
        drawSides(scene, pixels);
    m_readingProbe = false;
    if (m_probeAgainstSideB && scene.compare.mode != CompareMode::Difference)
        readSideBAtProbe(scene, pixels);
    glDisable(GL_SCISSOR_TEST);
    drawProbe(scene, pixels);
    glUseProgram(0);
    // Leave the depth test off, as Qt's own GL painting (QOpenGLWidget composition, QPainter)
    // expects to find it.
    glDisable(GL_DEPTH_TEST);
}

void Renderer::drawView(const Scene &scene, const BuiltProgram &program, QRect view, QRect clip,
                        int frameHeight)
{
    setViewportRect(view, frameHeight);
    glScissor(clip.x(), frameHeight - clip.y() - clip.height(), std::max(clip.width(), 0),
              clip.height());
    glClearColor(kBackgroundRgb[0], kBackgroundRgb[1], kBackgroundRgb[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (view.isEmpty() || clip.isEmpty())
        return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    const float aspect = float(view.width()) / float(view.height());
    drawObjects(scene, program, aspect);
    // Looked at once every visible object is there to draw (a mesh still loading is no
    // program's fault) and at least one is.
    if (m_lookPending && &program == &m_user && view == clip && drawsEveryVisibleObject(scene) &&
        scene.compare.mode == CompareMode::Off) {
        std::vector<std::uint8_t> rgba(std::size_t(view.width()) * std::size_t(view.height()) * 4);
        glReadPixels(view.x(), frameHeight - view.y() - view.height(), view.width(), view.height(),
                     GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        m_frameLook = lb::frameLook(rgba.data(), rgba.size() / 4);
        m_lookPending = false;
    }
    if (m_readingProbe && clip.contains(m_probePixel))
        m_probedColour = readPixel(m_probePixel, frameHeight);
    drawNormalLines(scene, aspect);

    // A program that hard-codes its light (the slides' constants) gets no marker at the
    // panel's position, where its light is not.
    if (scene.showLight && program.build.readsLightPosition()) {
        const Frames frames = computeFrames(scene, aspect);
        for (int i = 0; i < kMaxLights; ++i)
            if (scene.lights[std::size_t(i)].enabled)
                m_overlays.drawLightMarker(*this, scene.lights[std::size_t(i)], i, frames);
    }
    glDisable(GL_DEPTH_TEST);
}

bool Renderer::drawsEveryVisibleObject(const Scene &scene) const
{
    if (m_objects.size() < scene.objects.size())
        return false;
    bool any = false;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].visible) {
            if (!m_objects[i]->gpu.hasTriangles())
                return false;
            any = true;
        }
    return any;
}

void Renderer::drawObjects(const Scene &scene, const BuiltProgram &program, float aspect)
{
    // The view is opaque, as a desktop window's framebuffer is: the colour a program writes is
    // the colour shown, whatever its alpha. opengl-tutorial.org's `out vec3 color` leaves alpha
    // undefined (llvmpipe writes 0), and a frame read as premultiplied was black there.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    const int count = std::min(int(scene.objects.size()), int(m_objects.size()));
    for (int i = 0; i < count; ++i) {
        const ObjectSettings &object = scene.objects[std::size_t(i)];
        const GpuObject &o = *m_objects[std::size_t(i)];
        if (!object.visible || !o.gpu.hasTriangles())
            continue;
        const Frames frames = computeFrames(scene, aspect, i);
        glUseProgram(program.program.id());
        uploadUniforms(*this, program.build.uniforms, scene, frames);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, o.textureGl ? o.textureGl->id() : m_checkerTexture.id());
        applySampling(*this, object.sampling); // objects sharing the checker differ in this
        if (object.culls()) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(mirrors(frames) ? GL_CW : GL_CCW);
        }
        o.gpu.draw(*this);
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void Renderer::drawNormalLines(const Scene &scene, float aspect)
{
    const int count = std::min(int(scene.objects.size()), int(m_objects.size()));
    for (int i = 0; i < count; ++i) {
        const ObjectSettings &object = scene.objects[std::size_t(i)];
        const GpuObject &o = *m_objects[std::size_t(i)];
        if (object.visible && object.showNormals && o.gpu.hasTriangles())
            m_overlays.drawNormals(*this, o.gpu, scene, computeFrames(scene, aspect, i));
    }
}

} // namespace lb
