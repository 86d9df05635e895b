#include "offscreen.h"

#include "message_text.h"
#include "program_route.h"
#include "texture_file.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QOpenGLFunctions>

namespace lb {

void setDefaultGlFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // A driver that resets the context (a program ran too long) says so (context_loss.h).
    format.setOption(QSurfaceFormat::ResetNotification);
    QSurfaceFormat::setDefaultFormat(format);
}

OffscreenRenderer::~OffscreenRenderer()
{
    if (m_context.isValid() && m_context.makeCurrent(&m_surface)) {
        m_renderer.cleanup();
        m_fbo.reset();
        m_context.doneCurrent();
    }
}

namespace {
// The translation context of this file's messages.
struct OffscreenMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Offscreen)
};
} // namespace

QString OffscreenRenderer::initialize(QSize size)
{
    m_size = size;
    m_surface.setFormat(QSurfaceFormat::defaultFormat());
    m_surface.create();
    m_context.setFormat(QSurfaceFormat::defaultFormat());
    if (!m_context.create())
        return OffscreenMessages::tr(
            "cannot create an OpenGL context (is there an X server with OpenGL?)");
    if (!m_context.makeCurrent(&m_surface))
        return OffscreenMessages::tr("cannot make the OpenGL context current");
    m_resetStatus.attach(&m_context);
    const QSurfaceFormat f = m_context.format();
    if (f.majorVersion() * 10 + f.minorVersion() < 33)
        return OffscreenMessages::tr("OpenGL 3.3 is needed, the driver gives %1.%2")
            .arg(f.majorVersion())
            .arg(f.minorVersion());
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setInternalTextureFormat(GL_RGBA8);
    m_fbo = std::make_unique<QOpenGLFramebufferObject>(size, format);
    if (!m_fbo->isValid())
        return OffscreenMessages::tr("cannot create a %1x%2 framebuffer")
            .arg(size.width())
            .arg(size.height());
    return m_renderer.initialize();
}

bool OffscreenRenderer::wasReset()
{
    m_context.makeCurrent(&m_surface);
    return m_resetStatus.wasReset();
}

void OffscreenRenderer::addTextureFile(const QString &path, std::shared_ptr<const Texture> texture)
{
    if (texture)
        m_textures[path] = std::move(texture);
}

QString OffscreenRenderer::readTextureFiles(const Scene &scene)
{
    for (const ObjectSettings &o : scene.objects) {
        if (o.textureFile.isEmpty() || m_textures.count(o.textureFile))
            continue;
        const TextureFileRead read = readTextureFile(o.textureFile);
        if (!read.texture)
            return read.error;
        addTextureFile(o.textureFile, read.texture);
    }
    return {};
}

void OffscreenRenderer::addMeshFile(std::shared_ptr<const MeshFile> file)
{
    if (file)
        m_files[file->path] = std::move(file);
}

void OffscreenRenderer::setObjectMesh(std::shared_ptr<const Mesh> mesh)
{
    m_renderer.setObjectCount(1);
    m_renderer.setObject(0, std::move(mesh), nullptr);
    m_meshGiven = true;
}

const Mesh &OffscreenRenderer::objectMesh(const Scene &scene, int index)
{
    if (m_gpuOnly) // the file's mesh is gone: rebuilding would draw the panel's shape
        qFatal("lightbench: OffscreenRenderer::objectMesh() after dropCpuMeshes()");
    index = std::clamp(index, 0, int(scene.objects.size()) - 1);
    if (m_meshGiven) {
        static const Mesh none;
        const Mesh *given = m_renderer.objectMesh(index);
        return given ? *given : none;
    }
    const ObjectSettings &object = scene.objects[std::size_t(index)];
    const auto found = m_files.find(object.meshPath);
    const MeshFile *file =
        object.meshPath.isEmpty() || found == m_files.end() ? nullptr : found->second.get();
    const ObjectMeshKey key = objectMeshKey(object, file);
    if (m_keys.size() < scene.objects.size())
        m_keys.resize(scene.objects.size());
    std::optional<ObjectMeshKey> &built = m_keys[std::size_t(index)];
    std::shared_ptr<const Texture> texture = file ? file->texture : nullptr;
    if (const auto image = m_textures.find(object.textureFile); image != m_textures.end())
        texture = image->second;
    if (key != built || !m_renderer.objectMesh(index)) {
        m_remarks.resize(m_keys.size());
        m_renderer.setObject(
            index, buildObjectMesh(object, file, nullptr, &m_remarks[std::size_t(index)]), texture);
        built = key;
    } else {
        m_renderer.setObject(index, m_renderer.sharedObjectMesh(index), texture);
    }
    return *m_renderer.objectMesh(index);
}

ProbedObjects OffscreenRenderer::probedObjects(const Scene &scene)
{
    prepareObjects(scene);
    return m_renderer.probedObjects();
}

void OffscreenRenderer::prepareObjects(const Scene &scene)
{
    if (m_gpuOnly || m_meshGiven)
        return;
    m_context.makeCurrent(&m_surface); // fewer objects release their buffers
    m_renderer.setObjectCount(int(scene.objects.size()));
    m_keys.resize(scene.objects.size());
    for (int i = 0; i < int(scene.objects.size()); ++i)
        objectMesh(scene, i);
}

QStringList OffscreenRenderer::facesRemarks(const Scene &scene)
{
    prepareObjects(scene);
    QStringList lines;
    for (std::size_t i = 0; i < scene.objects.size() && i < m_remarks.size(); ++i) {
        if (m_remarks[i].isEmpty())
            continue;
        const QString line =
            escapedName(QFileInfo(scene.objects[i].meshPath).fileName()) + ": " + m_remarks[i];
        if (!lines.contains(line))
            lines << line;
    }
    return lines;
}

void OffscreenRenderer::dropCpuMeshes(const Scene &scene)
{
    prepareObjects(scene);
    // The files' meshes go before the upload: the objects' meshes are built from them by now
    // (or are them, sharing them), and the driver's copies of a 10M-triangle scan would
    // otherwise be made while its file's mesh (180 MB) is still held.
    m_files.clear();
    m_context.makeCurrent(&m_surface);
    m_renderer.uploadObjectsAndDropMeshes();
    m_gpuOnly = true;
}

QImage OffscreenRenderer::render(const Scene &scene)
{
    prepareObjects(scene);
    m_context.makeCurrent(&m_surface);
    m_fbo->bind();
    m_renderer.render(scene, m_size);
    QImage image = readFrame();
    m_fbo->release();
    return image;
}

QImage OffscreenRenderer::readFrame()
{
    // Read straight into the image that is returned: QOpenGLFramebufferObject::toImage and a
    // conversion to RGB32 made two more of 8 MB at 1920x1080. GL_BGRA bytes are QImage's
    // 0xAARRGGBB words on a little-endian machine.
    static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "GL_BGRA bytes read as 0xAARRGGBB words");
    QImage image(m_size, QImage::Format_ARGB32_Premultiplied);
    QOpenGLFunctions &gl = *m_context.functions();
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.glReadPixels(0, 0, m_size.width(), m_size.height(), GL_BGRA, GL_UNSIGNED_BYTE, image.bits());
    // A program that writes alpha below 1 gets what toImage() gave it (the framebuffer taken
    // as premultiplied, then made opaque), converted in place; opaque pixels are as read.
    bool opaque = true;
    for (int y = 0; y < image.height() && opaque; ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            opaque = opaque && qAlpha(row[x]) == 255;
    }
    if (opaque)
        image.reinterpretAsFormat(QImage::Format_RGB32);
    else
        image.convertTo(QImage::Format_RGB32);
    image.mirror(false, true); // rows top first, as --probe and QImage count them
    return image;
}

ProgramBuild OffscreenRenderer::useProgram(const QString &vertexSource,
                                           const QString &fragmentSource,
                                           const std::function<std::optional<Diagnostic>()> &trial,
                                           const UniformBindings &bindings)
{
    m_context.makeCurrent(&m_surface);
    return m_renderer.setUserProgram(vertexSource, fragmentSource, bindings, trial);
}

void OffscreenRenderer::renderFrames(const Scene &scene, int frames)
{
    prepareObjects(scene);
    m_context.makeCurrent(&m_surface);
    m_fbo->bind();
    for (int i = 0; i < frames; ++i)
        m_renderer.render(scene, m_size);
    m_context.functions()->glFinish();
    m_fbo->release();
}

double OffscreenRenderer::timeFrame(const Scene &scene, QSize size)
{
    prepareObjects(scene);
    m_context.makeCurrent(&m_surface);
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    format.setInternalTextureFormat(GL_RGBA8);
    QOpenGLFramebufferObject fbo(size, format);
    fbo.bind();
    const double ms = m_renderer.renderTimed(scene, size);
    fbo.release();
    return ms;
}

TrialResult OffscreenRenderer::tryUserProgram(const Scene &scene, const QString &vertex,
                                              const QString &fragment, QSize target,
                                              double budgetMs, const TrialSizes &sizes)
{
    OffscreenProgramHost host(*this, scene);
    return tryIn(host, {vertex, fragment, scene.bindings}, {target, budgetMs, sizes});
}

} // namespace lb
