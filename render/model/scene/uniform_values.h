#pragma once
// What the workbench feeds each uniform of the semantic table (semantics.h), computed from
// the scene and its frames with no OpenGL: the renderer uploads these values in the type the
// shader declared, the overlays ask for their matrices the same way, and the unit tests check
// every semantic against the model.

#include "frames.h"
#include "scene.h"
#include "semantics.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace lb {

// A matrix (a mat3 uniform takes its upper 3x3) or up to four numbers (a vec3 takes xyz; a
// float, int, bool or sampler takes x).
struct UniformValue
{
    bool isMatrix = false;
    glm::mat4 matrix{1.0f};
    glm::vec4 vector{0.0f};

    static UniformValue ofMatrix(const glm::mat4 &m) { return {true, m, glm::vec4(0.0f)}; }
    static UniformValue ofVector(const glm::vec4 &v) { return {false, glm::mat4(1.0f), v}; }
    static UniformValue ofNumber(float x) { return ofVector(glm::vec4(x)); }
};

// `light` (0 for light 1) chooses the light for the per-light semantics (isPerLight); a light
// switched off gives black colours, so a shader that ignores uLightEnabled adds nothing.
UniformValue uniformValue(Semantic semantic, const Scene &scene, const Frames &frames,
                          int light = 0);

} // namespace lb
