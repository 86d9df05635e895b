#include "uniform_upload.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>

namespace lb {

void uploadValues(QOpenGLExtraFunctions &gl, const ActiveUniform &u, const UniformValue *v, int n)
{
    n = std::clamp(n, 0, kMaxLights);
    if (u.location < 0 || n == 0)
        return;
    if (u.kind == UniformKind::Matrix) {
        if (!v[0].isMatrix)
            return;
        if (u.width == 4)
            gl.glUniformMatrix4fv(u.location, 1, GL_FALSE, glm::value_ptr(v[0].matrix));
        else if (u.width == 3)
            gl.glUniformMatrix3fv(u.location, 1, GL_FALSE, glm::value_ptr(glm::mat3(v[0].matrix)));
        return;
    }
    const int w = std::clamp(u.width, 1, 4);
    if (u.kind == UniformKind::Float) {
        std::array<GLfloat, 4 * kMaxLights> f{};
        for (int k = 0; k < n; ++k)
            std::copy_n(glm::value_ptr(v[k].vector), w, &f[std::size_t(w * k)]);
        using Set = void (QOpenGLExtraFunctions::*)(GLint, GLsizei, const GLfloat *);
        const Set set[4] = {
            &QOpenGLExtraFunctions::glUniform1fv, &QOpenGLExtraFunctions::glUniform2fv,
            &QOpenGLExtraFunctions::glUniform3fv, &QOpenGLExtraFunctions::glUniform4fv};
        (gl.*set[w - 1])(u.location, n, f.data());
    } else if (u.isInteger() || u.kind == UniformKind::Sampler) {
        std::array<GLint, 4 * kMaxLights> i{};
        for (int k = 0; k < n; ++k)
            for (int c = 0; c < w; ++c)
                i[std::size_t(w * k + c)] = GLint(v[k].vector[c]);
        using Set = void (QOpenGLExtraFunctions::*)(GLint, GLsizei, const GLint *);
        const Set set[4] = {
            &QOpenGLExtraFunctions::glUniform1iv, &QOpenGLExtraFunctions::glUniform2iv,
            &QOpenGLExtraFunctions::glUniform3iv, &QOpenGLExtraFunctions::glUniform4iv};
        (gl.*set[w - 1])(u.location, n, i.data());
    } // any other type: the shader keeps what it has
}

void uploadUniforms(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                    const Scene &scene, const Frames &frames)
{
    for (const ActiveUniform &u : uniforms) {
        if (u.semantic) {
            std::array<UniformValue, kMaxLights> values;
            const int n = isPerLight(*u.semantic) ? std::clamp(u.size, 1, kMaxLights) : 1;
            for (int i = 0; i < n; ++i)
                values[std::size_t(i)] = uniformValue(*u.semantic, scene, frames, i);
            uploadValues(gl, u, values.data(), n);
            continue;
        }
        const auto it = scene.shaderValues.find(u.name);
        const int n = u.components();
        if (it == scene.shaderValues.end() || n == 0 || int(it->second.size()) != n)
            continue; // the program keeps the value it has (its initializer, at first)
        UniformValue value;
        std::copy_n(it->second.begin(), n, glm::value_ptr(value.vector));
        uploadValues(gl, u, &value, 1);
    }
}

void uploadSemantic(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                    Semantic semantic, const UniformValue &value)
{
    for (const ActiveUniform &u : uniforms)
        if (u.semantic == semantic)
            uploadValues(gl, u, &value, 1);
}

void uploadNamed(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                 const QString &name, const UniformValue &value)
{
    for (const ActiveUniform &u : uniforms)
        if (u.name == name)
            uploadValues(gl, u, &value, 1);
}

} // namespace lb
