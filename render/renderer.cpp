#include "renderer.h"

#include "glsl/program.h"

#include <QFile>

#include <glm/common.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace lb {

namespace {

constexpr glm::vec3 kBackground{0.16f, 0.17f, 0.19f};

QString readResource(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll());
}

// Builds a built-in program from shaders/ (compiled into the resources).
GLuint builtInProgram(QOpenGLExtraFunctions &gl, const QString &name, QString &error)
{
    const ProgramBuild build = buildProgram(gl, readResource(":/shaders/" + name + ".vert"),
                                            readResource(":/shaders/" + name + ".frag"));
    if (!build.ok())
        error += "built-in shader '" + name + "' failed: " + build.log + '\n';
    return build.program;
}

// A marker's matrix in eye space: +Z of the arrow along `forward`, starting at `origin`.
glm::mat4 orientAlong(const glm::vec3 &origin, const glm::vec3 &forward, float length)
{
    const glm::vec3 z = glm::normalize(forward);
    const glm::vec3 helper = std::abs(z.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 x = glm::normalize(glm::cross(helper, z));
    const glm::vec3 y = glm::cross(z, x);
    glm::mat4 m(glm::vec4(x, 0), glm::vec4(y, 0), glm::vec4(z, 0), glm::vec4(origin, 1));
    return glm::scale(m, glm::vec3(length));
}

} // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

QString Renderer::initialize()
{
    initializeOpenGLFunctions();
    QString error;
    m_gouraud = builtInProgram(*this, "gouraud", error);
    m_phong = builtInProgram(*this, "phong", error);
    m_unlit = builtInProgram(*this, "unlit", error);
    if (!error.isEmpty())
        return error;

    const QImage &img = m_checker.image();
    glGenTextures(1, &m_texture);
    glBindTexture(GL_TEXTURE_2D, m_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width(), img.height(), 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, img.constBits());
    // Plain bilinear without mipmaps: CheckerTexture::sample() repeats exactly this lookup.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);

    upload(m_markerSphere, makeSphere(16, 8));
    upload(m_markerArrow, makeArrow(24));
    m_initialized = true;
    return {};
}

void Renderer::cleanup()
{
    if (!m_initialized)
        return;
    destroy(m_object);
    destroy(m_markerSphere);
    destroy(m_markerArrow);
    m_objectUploaded = false;
    glDeleteProgram(m_gouraud);
    glDeleteProgram(m_phong);
    glDeleteProgram(m_unlit);
    glDeleteTextures(1, &m_texture);
    m_gouraud = m_phong = m_unlit = m_texture = 0;
    m_initialized = false;
}

const Mesh &Renderer::meshFor(const ObjectSettings &object)
{
    if (object.shape != m_objectShape || object.tessellation != m_objectTessellation) {
        m_objectMesh = makeShape(object.shape, object.tessellation);
        m_objectShape = object.shape;
        m_objectTessellation = object.tessellation;
        m_objectUploaded = false;
    }
    return m_objectMesh;
}

void Renderer::upload(GpuMesh &gpu, const Mesh &mesh)
{
    if (!gpu.vao.isCreated())
        gpu.vao.create();
    gpu.vao.bind();
    const void *data[4] = {mesh.positions.data(), mesh.normals.data(), mesh.colors.data(),
                           mesh.uvs.data()};
    const int sizes[4] = {3, 3, 3, 2};
    const GLuint locations[4] = {kPositionSlot, kNormalSlot, kColorSlot, kTexCoordSlot};
    for (int i = 0; i < 4; ++i) {
        QOpenGLBuffer &buffer = gpu.attributes[std::size_t(i)];
        if (!buffer.isCreated())
            buffer.create();
        buffer.bind();
        buffer.allocate(data[i], int(mesh.vertexCount() * std::size_t(sizes[i]) * sizeof(float)));
        glEnableVertexAttribArray(locations[i]);
        glVertexAttribPointer(locations[i], sizes[i], GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    if (!gpu.indices.isCreated())
        gpu.indices.create();
    gpu.indices.bind();
    gpu.indices.allocate(mesh.indices.data(), int(mesh.indices.size() * sizeof(std::uint32_t)));
    gpu.indexCount = GLsizei(mesh.indices.size());
    gpu.vao.release();
}

void Renderer::destroy(GpuMesh &gpu)
{
    for (QOpenGLBuffer &b : gpu.attributes)
        b.destroy();
    gpu.indices.destroy();
    gpu.vao.destroy();
    gpu.indexCount = 0;
}

void Renderer::draw(GpuMesh &gpu)
{
    gpu.vao.bind();
    glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    gpu.vao.release();
}

void Renderer::setLightingUniforms(GLuint program, const Scene &scene, const Frames &frames)
{
    auto loc = [&](const char *name) { return glGetUniformLocation(program, name); };
    auto mat4 = [&](const char *name, const glm::mat4 &m) {
        glUniformMatrix4fv(loc(name), 1, GL_FALSE, glm::value_ptr(m));
    };
    auto vec3 = [&](const char *name, const glm::vec3 &v) {
        glUniform3fv(loc(name), 1, glm::value_ptr(v));
    };
    mat4("mModelView", frames.modelView);
    mat4("mNormals", frames.normals);
    mat4("mView", frames.view);
    mat4("mViewNormals", frames.viewNormals);
    mat4("mProjection", frames.projection);

    glUniform4fv(loc("lightPosition"), 1, glm::value_ptr(scene.light.position));
    glUniform1i(loc("uLightFrame"), int(scene.light.frame));
    vec3("lightAmb", scene.light.colors.ia);
    vec3("lightDif", scene.light.colors.id);
    vec3("lightSpe", scene.light.colors.is);
    vec3("materialAmb", scene.material.ka);
    vec3("materialDif", scene.material.kd);
    vec3("materialSpe", scene.material.ks);
    glUniform1f(loc("shininess"), scene.material.shininess);
    glUniform1i(loc("uSpecularModel"), scene.shading.specular == SpecularModel::Blinn ? 1 : 0);
    glUniform1i(loc("uProjection"), scene.shading.projection == Projection::Perspective ? 0 : 1);
    glUniform1i(loc("uEnableLighting"), scene.shading.lighting);
    glUniform1i(loc("uEnableVertexColor"), scene.shading.vertexColors);
    glUniform1i(loc("uEnableTexture"), scene.shading.texture);
    glUniform1i(loc("uSampler"), 0);
}

void Renderer::drawLightMarker(const Scene &scene, const Frames &frames)
{
    const glm::vec4 light = lightInEye(frames, scene.light.position, scene.light.frame);
    glm::mat4 modelView;
    GpuMesh *marker = nullptr;
    if (light.w != 0.0f) {
        modelView = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(light)), glm::vec3(0.06f));
        marker = &m_markerSphere;
    } else {
        // An arrow outside the object, pointing along the light's rays towards it.
        const glm::vec3 centre(frames.modelView[3]);
        const glm::vec3 towardsLight = glm::normalize(glm::vec3(light));
        modelView = orientAlong(centre + 2.2f * towardsLight, -towardsLight, 0.7f);
        marker = &m_markerArrow;
    }
    // The marker takes the light's diffuse colour at full brightness, so it stays visible.
    const glm::vec3 id = scene.light.colors.id;
    const float peak = glm::max(id.x, glm::max(id.y, id.z));
    const glm::vec3 colour = peak > 0.0f ? id / peak : glm::vec3(1.0f);

    glUseProgram(m_unlit);
    glUniformMatrix4fv(glGetUniformLocation(m_unlit, "mModelView"), 1, GL_FALSE,
                       glm::value_ptr(modelView));
    glUniformMatrix4fv(glGetUniformLocation(m_unlit, "mProjection"), 1, GL_FALSE,
                       glm::value_ptr(frames.projection));
    glUniform3fv(glGetUniformLocation(m_unlit, "uColor"), 1, glm::value_ptr(colour));
    draw(*marker);
}

void Renderer::render(const Scene &scene, QSize pixels)
{
    if (!m_initialized || pixels.isEmpty())
        return;
    const Mesh &mesh = meshFor(scene.object);
    if (!m_objectUploaded) {
        upload(m_object, mesh);
        m_objectUploaded = true;
    }

    glViewport(0, 0, pixels.width(), pixels.height());
    glClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    const Frames frames = computeFrames(scene, float(pixels.width()) / float(pixels.height()));
    const GLuint program = scene.shading.shading == Shading::Gouraud ? m_gouraud : m_phong;
    glUseProgram(program);
    setLightingUniforms(program, scene, frames);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_texture);
    draw(m_object);
    glBindTexture(GL_TEXTURE_2D, 0);

    if (scene.showLight)
        drawLightMarker(scene, frames);
    glUseProgram(0);
}

} // namespace lb
