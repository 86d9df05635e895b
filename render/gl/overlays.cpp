#include "overlays.h"

#include "uniform_upload.h"

#include <glm/common.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/scalar_constants.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace lb {

namespace {

// The overlay programs' own inputs (shaders/unlit.frag, shaders/normals.vert). They are not
// scene values, so they are not in the semantic table: a user's uColor stays the user's.
const QString kColour = QStringLiteral("uColor");
const QString kLineLength = QStringLiteral("uLineLength");

// Unit axes x, y, z with z along `forward` (any x, y square to it).
glm::mat3 axesAlong(const glm::vec3 &forward)
{
    const glm::vec3 z = glm::normalize(forward);
    const glm::vec3 helper = std::abs(z.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 x = glm::normalize(glm::cross(helper, z));
    return glm::mat3(x, glm::cross(z, x), z);
}

// A marker's matrix in eye space: +Z of the arrow along `forward`, starting at `origin`.
glm::mat4 orientAlong(const glm::vec3 &origin, const glm::vec3 &forward, float length)
{
    glm::mat4 m(axesAlong(forward));
    m[3] = glm::vec4(origin, 1.0f);
    return glm::scale(m, glm::vec3(length));
}

} // namespace

QString Overlays::initialize(QOpenGLExtraFunctions &gl)
{
    QString error;
    m_unlit = buildBuiltIn(gl, "unlit", error);
    m_normals = buildBuiltIn(gl, "normals", error, "unlit");
    m_sphere.upload(gl, makeSphere(16, 8));
    m_arrow.upload(gl, makeArrow(24));
    return error;
}

void Overlays::release()
{
    m_unlit = {};
    m_normals = {};
    m_sphere.release();
    m_arrow.release();
}

void Overlays::useUnlit(QOpenGLExtraFunctions &gl, const glm::mat4 &modelView,
                        const glm::mat4 &projection, const glm::vec3 &colour)
{
    gl.glUseProgram(m_unlit.program.id());
    const std::vector<ActiveUniform> &uniforms = m_unlit.build.uniforms;
    uploadSemantic(gl, uniforms, Semantic::ModelView, UniformValue::ofMatrix(modelView));
    uploadSemantic(gl, uniforms, Semantic::Projection, UniformValue::ofMatrix(projection));
    uploadNamed(gl, uniforms, kColour, UniformValue::ofVector(glm::vec4(colour, 1.0f)));
}

void Overlays::drawLightMarker(QOpenGLExtraFunctions &gl, const Light &light, int index,
                               const Frames &frames)
{
    const glm::vec4 eye = lightInEye(frames, index, light.position, light.frame);
    glm::mat4 modelView;
    const GpuMesh *marker = nullptr;
    if (eye.w != 0.0f) {
        modelView = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(eye)), glm::vec3(0.06f));
        marker = &m_sphere;
    } else {
        // An arrow outside the object the light belongs to, along the light's rays towards it.
        const glm::vec3 centre(frames.lightModelView[std::size_t(index)][3]);
        const glm::vec3 towardsLight = glm::normalize(glm::vec3(eye));
        modelView = orientAlong(centre + 2.2f * towardsLight, -towardsLight, 0.7f);
        marker = &m_arrow;
    }
    // The marker takes the light's diffuse colour at full brightness, so it stays visible.
    const glm::vec3 id = light.colors.id;
    const float peak = glm::max(id.x, glm::max(id.y, id.z));
    const glm::vec3 colour = peak > 0.0f ? id / peak : glm::vec3(1.0f);
    useUnlit(gl, modelView, frames.projection, colour);
    marker->draw(gl);
    if (eye.w == 0.0f || light.spot.cutoffDegrees >= limits::kMaxSpotCutoff)
        return;
    // A spotlight: eight rays along the cone's edge, from the light.
    const glm::mat3 axes = axesAlong(spotDirectionInEye(frames, index, light));
    const float cutoff = glm::radians(light.spot.cutoffDegrees);
    constexpr int kRays = 8;
    for (int k = 0; k < kRays; ++k) {
        const float around = 2.0f * glm::pi<float>() * float(k) / float(kRays);
        const glm::vec3 ray =
            axes * glm::vec3(std::sin(cutoff) * std::cos(around),
                             std::sin(cutoff) * std::sin(around), std::cos(cutoff));
        useUnlit(gl, orientAlong(glm::vec3(eye), ray, 0.45f), frames.projection, colour);
        m_arrow.draw(gl);
    }
}

void Overlays::drawNormals(QOpenGLExtraFunctions &gl, const GpuMesh &mesh, const Scene &scene,
                           const Frames &frames)
{
    gl.glUseProgram(m_normals.program.id());
    const std::vector<ActiveUniform> &uniforms = m_normals.build.uniforms;
    for (Semantic s : {Semantic::ModelView, Semantic::Normals, Semantic::Projection})
        uploadSemantic(gl, uniforms, s, uniformValue(s, scene, frames));
    const glm::vec3 &scale = scene.objects[std::size_t(frames.object)].scale;
    const float length = 0.05f * (scale.x + scale.y + scale.z) / 3.0f;
    uploadNamed(gl, uniforms, kLineLength, UniformValue::ofNumber(length));
    uploadNamed(gl, uniforms, kColour, UniformValue::ofVector(glm::vec4(1.0f, 0.82f, 0.2f, 1.0f)));
    mesh.drawNormalLines(gl);
}

void Overlays::drawArrows(QOpenGLExtraFunctions &gl, const std::vector<ProbeArrow> &arrows,
                          const Frames &frames, bool faded)
{
    if (faded) { // a constant alpha: the unlit program needs no change
        gl.glEnable(GL_BLEND);
        gl.glBlendColor(0.0f, 0.0f, 0.0f, 0.4f);
        gl.glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    }
    for (const ProbeArrow &a : arrows) {
        const float length = glm::length(a.direction);
        if (length <= 0.0f)
            continue;
        glm::mat4 modelView = orientAlong(a.origin, a.direction, length);
        if (faded) // thinner across, as long
            modelView = glm::scale(modelView, glm::vec3(0.5f, 0.5f, 1.0f));
        useUnlit(gl, modelView, frames.projection, a.colour);
        m_arrow.draw(gl);
    }
    if (faded)
        gl.glDisable(GL_BLEND);
}

} // namespace lb
