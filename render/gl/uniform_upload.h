#pragma once
// The typed upload: values from the model (uniform_values.h) or the user's own controls go
// to a linked program in the type its GLSL declares. Call with the program in use.

#include "frames.h"
#include "program_build.h"
#include "scene.h"
#include "uniform_values.h"

#include <QOpenGLExtraFunctions>

#include <vector>

namespace lb {

// Every uniform of the program: those of the semantic table get the scene's values (an array
// of a per-light semantic gets one light per element, a plain one light 1), the others the
// values the user gave them (Scene::shaderValues), or keep what they have.
void uploadUniforms(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                    const Scene &scene, const Frames &frames);

// `value` into each uniform that has `semantic` (the overlays' matrices).
void uploadSemantic(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                    Semantic semantic, const UniformValue &value);

// `value` into the uniform called `name`: the workbench's own programs' inputs that are not
// scene values (an overlay's colour, the difference view's textures).
void uploadNamed(QOpenGLExtraFunctions &gl, const std::vector<ActiveUniform> &uniforms,
                 const QString &name, const UniformValue &value);

// Up to `n` values into a uniform (an array's first n elements), in its declared type: a
// mat3 takes the upper 3x3, a vec3 xyz, an int or bool the first number rounded down.
void uploadValues(QOpenGLExtraFunctions &gl, const ActiveUniform &uniform,
                  const UniformValue *values, int n);

} // namespace lb
