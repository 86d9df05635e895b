#include "renderer.h"

#include "presets.h"
#include "program.h"

#include <glm/common.hpp>

#include <algorithm>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace lb {

namespace {

constexpr glm::vec3 kBackground{0.16f, 0.17f, 0.19f};

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
    m_gouraud = builtIn("gouraud", error);
    m_phong = builtIn("phong", error);
    m_unlit = builtIn("unlit", error);
    m_normals = builtIn("normals", error, "unlit");
    m_differenceProgram = builtIn("difference", error);
    if (!error.isEmpty())
        return error;

    m_checkerId = uploadTexture(m_checker.image());
    upload(m_markerSphere, makeSphere(16, 8));
    upload(m_markerArrow, makeArrow(24));
    Mesh screen;
    screen.positions = {{-1.0f, -1.0f, 0.0f}, {3.0f, -1.0f, 0.0f}, {-1.0f, 3.0f, 0.0f}};
    screen.indices = {0, 1, 2};
    upload(m_screenTriangle, screen);
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
    m_sideFbo[0].reset();
    m_sideFbo[1].reset();
    destroy(m_screenTriangle);
    m_objectUploaded = m_objectTextureUploaded = false;
    for (Program *p : {&m_gouraud, &m_phong, &m_unlit, &m_normals, &m_differenceProgram, &m_user})
        release(*p);
    for (GLuint *id : {&m_checkerId, &m_objectTextureId}) {
        glDeleteTextures(1, id);
        *id = 0;
    }
    m_initialized = false;
}

GLuint Renderer::uploadTexture(const QImage &image)
{
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, image.constBits());
    // Plain bilinear without mipmaps: Texture::sample() repeats exactly this lookup.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return id;
}

Renderer::Program Renderer::builtIn(const QString &name, QString &error, const QString &fragment)
{
    const Preset pair{name, ":/shaders/" + name};
    const Preset fragmentPair{name, ":/shaders/" + (fragment.isEmpty() ? name : fragment)};
    ProgramBuild build = buildProgram(*this, pair.vertexSource(), fragmentPair.fragmentSource());
    if (!build.ok())
        error += "built-in shader '" + name + "' failed:\n" + build.log();
    return Program{build.program, std::move(build.uniforms)};
}

GLint Renderer::uniformLocation(const Program &program, const char *name)
{
    for (const ActiveUniform &u : program.uniforms) // reflected at link time: no GL call
        if (u.name == QLatin1String(name))
            return u.location;
    return -1;
}

void Renderer::release(Program &program)
{
    glDeleteProgram(program.id);
    program = Program{};
}

ProgramBuild Renderer::setUserProgram(const QString &vertexSource, const QString &fragmentSource)
{
    ProgramBuild build = buildProgram(*this, vertexSource, fragmentSource);
    if (build.ok()) {
        release(m_user);
        m_user = Program{build.program, build.uniforms};
    }
    return build;
}

const Renderer::Program &Renderer::objectProgram(const Scene &scene) const
{
    return m_user.id ? m_user : builtInProgram(scene);
}

const Renderer::Program &Renderer::builtInProgram(const Scene &scene) const
{
    return scene.shading.shading == Shading::Gouraud ? m_gouraud : m_phong;
}

void Renderer::setObject(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const Texture> texture)
{
    if (mesh != m_objectMesh)
        m_objectUploaded = false;
    m_objectMesh = std::move(mesh);
    if (texture != m_objectTexture)
        m_objectTextureUploaded = false;
    m_objectTexture = std::move(texture);
}

void Renderer::upload(GpuMesh &gpu, const Mesh &mesh)
{
    // Normals go up with w = 0, so a shader that declares vNormal as vec4 (the slides do)
    // reads a direction; positions go up as vec3 and GL supplies w = 1.
    std::vector<glm::vec4> normals;
    normals.reserve(mesh.normals.size());
    for (const glm::vec3 &n : mesh.normals)
        normals.emplace_back(n, 0.0f);
    const std::size_t n = mesh.vertexCount();
    gpu.colors = mesh.colors.size() == n;
    gpu.uvs = mesh.uvs.size() == n;
    gpu.vertexCount = GLsizei(n);
    const void *data[4] = {mesh.positions.data(), normals.data(), mesh.colors.data(),
                           mesh.uvs.data()};
    const bool present[4] = {true, normals.size() == n, gpu.colors, gpu.uvs};
    const int sizes[4] = {3, 4, 3, 2};
    const GLuint locations[4] = {kPositionSlot, kNormalSlot, kColorSlot, kTexCoordSlot};
    for (QOpenGLVertexArrayObject *vao : {&gpu.vao, &gpu.normalLines})
        if (!vao->isCreated())
            vao->create();
    for (int i = 0; i < 4; ++i) {
        QOpenGLBuffer &buffer = gpu.attributes[std::size_t(i)];
        if (!buffer.isCreated())
            buffer.create();
        buffer.bind();
        buffer.allocate(present[i] ? data[i] : nullptr,
                        present[i] ? int(n * std::size_t(sizes[i]) * sizeof(float)) : 0);
        gpu.vao.bind();
        if (present[i]) {
            glEnableVertexAttribArray(locations[i]);
            glVertexAttribPointer(locations[i], sizes[i], GL_FLOAT, GL_FALSE, 0, nullptr);
        } else {
            glDisableVertexAttribArray(locations[i]);
        }
        if (i < 2) { // the normal lines read positions and normals once per line
            gpu.normalLines.bind();
            glEnableVertexAttribArray(locations[i]);
            glVertexAttribPointer(locations[i], sizes[i], GL_FLOAT, GL_FALSE, 0, nullptr);
            glVertexAttribDivisor(locations[i], 1);
        }
    }
    gpu.vao.bind();
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
    gpu.normalLines.destroy();
    gpu.indexCount = gpu.vertexCount = 0;
}

void Renderer::draw(GpuMesh &gpu)
{
    // Constant values for the arrays a mesh lacks: the reference (probe.cpp) reads the same.
    if (!gpu.colors)
        glVertexAttrib4f(kColorSlot, 1.0f, 1.0f, 1.0f, 1.0f);
    if (!gpu.uvs)
        glVertexAttrib4f(kTexCoordSlot, 0.0f, 0.0f, 0.0f, 1.0f);
    gpu.vao.bind();
    glDrawElements(GL_TRIANGLES, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    gpu.vao.release();
}

void Renderer::setUniforms(const Program &program, const Scene &scene, const Frames &frames)
{
    // Each value goes out in the type the shader declared: a normal matrix declared mat3
    // (the exercise's uNormalMatrix) gets the upper 3x3, a vec3 light position gets xyz, an
    // int or a bool the first number.
    auto matrix = [this](const ActiveUniform &u, const glm::mat4 &m) {
        if (u.type == GL_FLOAT_MAT4)
            glUniformMatrix4fv(u.location, 1, GL_FALSE, glm::value_ptr(m));
        else if (u.type == GL_FLOAT_MAT3)
            glUniformMatrix3fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat3(m)));
    };
    auto vector = [this](const ActiveUniform &u, const glm::vec4 &v) { setVectors(u, &v, 1); };
    // A light's value for each element of an array (light 1 for a plain uniform). A light
    // switched off goes out black, so a shader that ignores uLightEnabled still adds nothing.
    auto perLight = [&](const ActiveUniform &u, auto value) {
        std::array<glm::vec4, kMaxLights> values;
        const int n = std::clamp(int(u.size), 1, kMaxLights);
        for (int i = 0; i < n; ++i)
            values[std::size_t(i)] = value(scene.lights[std::size_t(i)]);
        setVectors(u, values.data(), n);
    };
    auto colour = [](const Light &l, const glm::vec3 &c) {
        return glm::vec4(l.enabled ? c : glm::vec3(0.0f), 1.0f);
    };
    const Material &material = scene.material;
    for (const ActiveUniform &u : program.uniforms) {
        if (!u.semantic) {
            setShaderValue(u, scene);
            continue;
        }
        switch (*u.semantic) {
        case Semantic::ModelView:
            matrix(u, frames.modelView);
            break;
        case Semantic::Normals:
            matrix(u, frames.normals);
            break;
        case Semantic::View:
            matrix(u, frames.view);
            break;
        case Semantic::ViewNormals:
            matrix(u, frames.viewNormals);
            break;
        case Semantic::Projection:
            matrix(u, frames.projection);
            break;
        case Semantic::LightPosition:
            perLight(u, [](const Light &l) { return l.position; });
            break;
        case Semantic::LightPositionEye:
            perLight(u, [&](const Light &l) { return lightInEye(frames, l.position, l.frame); });
            break;
        case Semantic::LightAmbient:
            perLight(u, [&](const Light &l) { return colour(l, l.colors.ia); });
            break;
        case Semantic::LightDiffuse:
            perLight(u, [&](const Light &l) { return colour(l, l.colors.id); });
            break;
        case Semantic::LightSpecular:
            perLight(u, [&](const Light &l) { return colour(l, l.colors.is); });
            break;
        case Semantic::LightFrame:
            perLight(u, [](const Light &l) { return glm::vec4(float(int(l.frame))); });
            break;
        case Semantic::LightEnabled:
            perLight(u, [](const Light &l) { return glm::vec4(l.enabled ? 1.0f : 0.0f); });
            break;
        case Semantic::MaterialAmbient:
            vector(u, glm::vec4(material.ka, 1.0f));
            break;
        case Semantic::MaterialDiffuse:
            vector(u, glm::vec4(material.kd, 1.0f));
            break;
        case Semantic::MaterialSpecular:
            vector(u, glm::vec4(material.ks, 1.0f));
            break;
        case Semantic::Shininess:
            vector(u, glm::vec4(material.shininess));
            break;
        case Semantic::SpecularModel:
            vector(u, glm::vec4(scene.shading.specular == SpecularModel::Blinn ? 1.0f : 0.0f));
            break;
        case Semantic::ProjectionKind:
            vector(u, glm::vec4(scene.shading.projection == Projection::Perspective ? 0.0f : 1.0f));
            break;
        case Semantic::EnableLighting:
            vector(u, glm::vec4(scene.shading.lighting ? 1.0f : 0.0f));
            break;
        case Semantic::EnableVertexColor:
            vector(u, glm::vec4(scene.shading.vertexColors ? 1.0f : 0.0f));
            break;
        case Semantic::EnableTexture:
            vector(u, glm::vec4(scene.shading.texture ? 1.0f : 0.0f));
            break;
        case Semantic::Sampler:
            vector(u, glm::vec4(0.0f));
            break;
        }
    }
}

void Renderer::setVectors(const ActiveUniform &u, const glm::vec4 *v, int n)
{
    std::array<GLfloat, 4 * kMaxLights> f{};
    std::array<GLint, kMaxLights> i{};
    n = std::min(n, kMaxLights);
    switch (u.type) {
    case GL_FLOAT_VEC4:
        glUniform4fv(u.location, n, glm::value_ptr(v[0]));
        break;
    case GL_FLOAT_VEC3:
        for (int k = 0; k < n; ++k)
            std::copy_n(glm::value_ptr(v[k]), 3, &f[std::size_t(3 * k)]);
        glUniform3fv(u.location, n, f.data());
        break;
    case GL_FLOAT:
        for (int k = 0; k < n; ++k)
            f[std::size_t(k)] = v[k].x;
        glUniform1fv(u.location, n, f.data());
        break;
    case GL_INT:
    case GL_BOOL:
    case GL_SAMPLER_2D:
        for (int k = 0; k < n; ++k)
            i[std::size_t(k)] = GLint(v[k].x);
        glUniform1iv(u.location, n, i.data());
        break;
    default:
        break; // a type this value cannot fill: the shader keeps what it has
    }
}

void Renderer::setShaderValue(const ActiveUniform &u, const Scene &scene)
{
    const auto it = scene.shaderValues.find(u.name);
    const int n = u.components();
    if (it == scene.shaderValues.end() || n == 0 || int(it->second.size()) != n)
        return; // the program keeps the value it has (its initializer, at first)
    const std::vector<float> &v = it->second;
    if (u.isInteger()) {
        const GLint i[4] = {GLint(v[0]), n > 1 ? GLint(v[1]) : 0, n > 2 ? GLint(v[2]) : 0,
                            n > 3 ? GLint(v[3]) : 0};
        const decltype(&QOpenGLExtraFunctions::glUniform1iv) set[4] = {
            &QOpenGLExtraFunctions::glUniform1iv, &QOpenGLExtraFunctions::glUniform2iv,
            &QOpenGLExtraFunctions::glUniform3iv, &QOpenGLExtraFunctions::glUniform4iv};
        (this->*set[n - 1])(u.location, 1, i);
    } else {
        const decltype(&QOpenGLExtraFunctions::glUniform1fv) set[4] = {
            &QOpenGLExtraFunctions::glUniform1fv, &QOpenGLExtraFunctions::glUniform2fv,
            &QOpenGLExtraFunctions::glUniform3fv, &QOpenGLExtraFunctions::glUniform4fv};
        (this->*set[n - 1])(u.location, 1, v.data());
    }
}

void Renderer::drawLightMarker(const Light &lightSettings, const Frames &frames)
{
    const glm::vec4 light = lightInEye(frames, lightSettings.position, lightSettings.frame);
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
    const glm::vec3 id = lightSettings.colors.id;
    const float peak = glm::max(id.x, glm::max(id.y, id.z));
    const glm::vec3 colour = peak > 0.0f ? id / peak : glm::vec3(1.0f);

    glUseProgram(m_unlit.id);
    glUniformMatrix4fv(uniformLocation(m_unlit, "mModelView"), 1, GL_FALSE,
                       glm::value_ptr(modelView));
    glUniformMatrix4fv(uniformLocation(m_unlit, "mProjection"), 1, GL_FALSE,
                       glm::value_ptr(frames.projection));
    glUniform3fv(uniformLocation(m_unlit, "uColor"), 1, glm::value_ptr(colour));
    draw(*marker);
}

void Renderer::drawNormals(const Scene &scene, const Frames &frames)
{
    const glm::vec3 lineColour(1.0f, 0.82f, 0.2f);
    glUseProgram(m_normals.id);
    glUniformMatrix4fv(uniformLocation(m_normals, "mModelView"), 1, GL_FALSE,
                       glm::value_ptr(frames.modelView));
    glUniformMatrix4fv(uniformLocation(m_normals, "mNormals"), 1, GL_FALSE,
                       glm::value_ptr(frames.normals));
    glUniformMatrix4fv(uniformLocation(m_normals, "mProjection"), 1, GL_FALSE,
                       glm::value_ptr(frames.projection));
    const glm::vec3 &s = scene.object.scale;
    glUniform1f(uniformLocation(m_normals, "uLineLength"), 0.05f * (s.x + s.y + s.z) / 3.0f);
    glUniform3fv(uniformLocation(m_normals, "uColor"), 1, glm::value_ptr(lineColour));
    m_object.normalLines.bind();
    glDrawArraysInstanced(GL_LINES, 0, 2, m_object.vertexCount);
    m_object.normalLines.release();
}

void Renderer::render(const Scene &scene, QSize pixels)
{
    if (!m_initialized || pixels.isEmpty())
        return;
    if (!m_objectUploaded) {
        if (m_objectMesh)
            upload(m_object, *m_objectMesh);
        else
            destroy(m_object);
        m_objectUploaded = true;
    }
    if (!m_objectTextureUploaded) {
        glDeleteTextures(1, &m_objectTextureId);
        m_objectTextureId = m_objectTexture ? uploadTexture(m_objectTexture->image()) : 0;
        m_objectTextureUploaded = true;
    }

    const QRect whole(QPoint(0, 0), pixels);
    glEnable(GL_SCISSOR_TEST);
    if (scene.compare.mode == CompareMode::Off) {
        drawView(scene, objectProgram(scene), whole, whole, pixels.height());
    } else if (scene.compare.mode == CompareMode::Difference) {
        drawDifference(scene, pixels);
    } else {
        // Side A left of the divider, B right of it: in halves, or across the wipe.
        const Scene sceneB = sceneOfSide(scene, true);
        const int divider = dividerColumn(scene, pixels);
        const bool wipe = scene.compare.mode == CompareMode::Wipe;
        for (bool sideB : {false, true}) {
            const QRect view = viewRect(scene, pixels, sideB);
            const QRect clip = !wipe ? view
                               : sideB
                                   ? QRect(divider, 0, pixels.width() - divider, pixels.height())
                                   : QRect(0, 0, divider, pixels.height());
            drawView(sideB ? sceneB : scene, sideB ? builtInProgram(sceneB) : objectProgram(scene),
                     view, clip, pixels.height());
        }
        drawDivider(divider, pixels);
    }
    glDisable(GL_SCISSOR_TEST);
    drawProbe(scene, pixels);
    glUseProgram(0);
    // Leave the depth test off, as Qt's own GL painting (QOpenGLWidget composition, QPainter)
    // expects to find it.
    glDisable(GL_DEPTH_TEST);
}

void Renderer::drawView(const Scene &scene, const Program &program, QRect view, QRect clip,
                        int frameHeight)
{
    // GL counts rows from the bottom.
    glViewport(view.x(), frameHeight - view.y() - view.height(), view.width(), view.height());
    glScissor(clip.x(), frameHeight - clip.y() - clip.height(), std::max(clip.width(), 0),
              clip.height());
    glClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (view.isEmpty() || clip.isEmpty())
        return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    const Frames frames = computeFrames(scene, float(view.width()) / float(view.height()));
    glUseProgram(program.id);
    setUniforms(program, scene, frames);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_objectTexture ? m_objectTextureId : m_checkerId);
    if (m_object.indexCount > 0)
        draw(m_object);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (scene.object.showNormals && m_object.vertexCount > 0)
        drawNormals(scene, frames);

    if (scene.showLight)
        for (const Light &light : scene.lights)
            if (light.enabled)
                drawLightMarker(light, frames);
    glDisable(GL_DEPTH_TEST);
}

void Renderer::setProbe(std::vector<Arrow> arrows, QPoint framePixel)
{
    m_probeArrows = std::move(arrows);
    m_probePixel = framePixel;
}

void Renderer::drawProbe(const Scene &scene, QSize pixels)
{
    m_probedColour.reset();
    const QPoint p = m_probePixel;
    if (p.x() >= 0 && p.y() >= 0 && p.x() < pixels.width() && p.y() < pixels.height()) {
        std::uint8_t rgba[4] = {0, 0, 0, 0};
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(p.x(), pixels.height() - 1 - p.y(), 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        m_probedColour = glm::ivec3(rgba[0], rgba[1], rgba[2]);
    }
    if (m_probeArrows.empty())
        return;
    glUseProgram(m_unlit.id);
    const bool split = scene.compare.mode == CompareMode::SideBySide;
    for (bool sideB : {false, true}) {
        if (sideB && !split)
            break;
        const QRect view = viewRect(scene, pixels, sideB);
        glViewport(view.x(), pixels.height() - view.y() - view.height(), view.width(),
                   view.height());
        const Frames frames = computeFrames(scene, float(view.width()) / float(view.height()));
        glUniformMatrix4fv(uniformLocation(m_unlit, "mProjection"), 1, GL_FALSE,
                           glm::value_ptr(frames.projection));
        for (const Arrow &a : m_probeArrows) {
            const float length = glm::length(a.direction);
            if (length <= 0.0f)
                continue;
            const glm::mat4 modelView = orientAlong(a.origin, a.direction, length);
            glUniformMatrix4fv(uniformLocation(m_unlit, "mModelView"), 1, GL_FALSE,
                               glm::value_ptr(modelView));
            glUniform3fv(uniformLocation(m_unlit, "uColor"), 1, glm::value_ptr(a.colour));
            draw(m_markerArrow);
        }
    }
}

void Renderer::drawDivider(int column, QSize frame)
{
    // A 2-pixel light line between the sides.
    glScissor(std::clamp(column - 1, 0, frame.width()), 0, 2, frame.height());
    glClearColor(0.85f, 0.85f, 0.85f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

void Renderer::drawDifference(const Scene &scene, QSize pixels)
{
    GLint target = 0; // the caller's framebuffer (QOpenGLWidget's is not 0)
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    const QRect whole(QPoint(0, 0), pixels);
    for (int side = 0; side < 2; ++side) {
        auto &fbo = m_sideFbo[side];
        if (!fbo || fbo->size() != pixels) {
            QOpenGLFramebufferObjectFormat format;
            format.setAttachment(QOpenGLFramebufferObject::Depth);
            fbo = std::make_unique<QOpenGLFramebufferObject>(pixels, format);
        }
        fbo->bind();
        const Scene sideScene = sceneOfSide(scene, side == 1);
        drawView(sideScene, side == 1 ? builtInProgram(sideScene) : objectProgram(scene), whole,
                 whole, pixels.height());
    }
    measureDifference(pixels);

    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    glViewport(0, 0, pixels.width(), pixels.height());
    glScissor(0, 0, pixels.width(), pixels.height());
    glUseProgram(m_differenceProgram.id);
    for (int side = 0; side < 2; ++side) {
        glActiveTexture(GL_TEXTURE0 + GLenum(side));
        glBindTexture(GL_TEXTURE_2D, m_sideFbo[side]->texture());
        glUniform1i(uniformLocation(m_differenceProgram, side ? "uB" : "uA"), side);
    }
    glUniform1f(uniformLocation(m_differenceProgram, "uScale"), kDifferenceScale);
    glUniform2f(uniformLocation(m_differenceProgram, "uPixels"), float(pixels.width()),
                float(pixels.height()));
    draw(m_screenTriangle);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void Renderer::measureDifference(QSize pixels)
{
    // Both sides back to the CPU: the largest difference is a number for the user, and a
    // GPU reduction for one number per frame is not worth its code at these sizes.
    const std::size_t n = std::size_t(pixels.width()) * std::size_t(pixels.height()) * 4;
    std::vector<std::uint8_t> side[2] = {std::vector<std::uint8_t>(n),
                                         std::vector<std::uint8_t>(n)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int s = 0; s < 2; ++s) {
        m_sideFbo[s]->bind();
        glReadPixels(0, 0, pixels.width(), pixels.height(), GL_RGBA, GL_UNSIGNED_BYTE,
                     side[s].data());
    }
    DifferenceStats stats;
    stats.valid = true;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < n; i += 4) {
        int d = 0;
        for (std::size_t c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(side[0][i + c]) - int(side[1][i + c])));
        differing += d > 0 ? 1 : 0;
        if (d > stats.largest) {
            stats.largest = d;
            const int p = int(i / 4);
            // Rows come bottom-up from GL.
            stats.at = QPoint(p % pixels.width(), pixels.height() - 1 - p / pixels.width());
        }
    }
    stats.differing = double(differing) / double(n / 4);
    m_difference = stats;
}

} // namespace lb
