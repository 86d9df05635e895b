#include "camera.h"

#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
constexpr float kNear = 0.05f;
constexpr float kFar = 100.0f;
constexpr float kMaxPitch = 89.0f;
} // namespace

glm::vec3 OrbitCamera::eye() const
{
    const float yaw = glm::radians(yawDegrees);
    const float pitch = glm::radians(pitchDegrees);
    const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                           std::cos(pitch) * std::cos(yaw));
    return target + distance * offset;
}

glm::mat4 OrbitCamera::view() const
{
    return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

float OrbitCamera::tanHalfFovY(float aspect)
{
    // A view narrower than it is high (a side-by-side half, a portrait window) keeps the
    // horizontal field a square view has, so the object fits its width instead of being cut.
    const float fit = aspect < 1.0f ? 1.0f / std::max(aspect, 1e-3f) : 1.0f;
    return std::tan(glm::radians(kFovYDegrees) * 0.5f) * fit;
}

glm::mat4 OrbitCamera::projection(float aspect, Projection kind) const
{
    const float tanHalf = tanHalfFovY(aspect);
    if (kind == Projection::Perspective)
        return glm::perspective(2.0f * std::atan(tanHalf), aspect, kNear, kFar);
    const float halfHeight = distance * tanHalf;
    const float halfWidth = halfHeight * aspect;
    return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, kNear, kFar);
}

void OrbitCamera::orbit(float dYawDegrees, float dPitchDegrees)
{
    yawDegrees = std::fmod(yawDegrees + dYawDegrees, 360.0f);
    pitchDegrees = glm::clamp(pitchDegrees + dPitchDegrees, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dxView, float dyView, float aspect)
{
    const glm::mat4 toWorld = glm::inverse(view());
    const glm::vec3 right(toWorld[0]);
    const glm::vec3 up(toWorld[1]);
    const float height = 2.0f * distance * tanHalfFovY(aspect); // as projection() shows it
    target += (-dxView * right + dyView * up) * height;
}

void OrbitCamera::zoom(float steps)
{
    distance = glm::clamp(distance * std::pow(0.9f, steps), 0.2f, 50.0f);
}

} // namespace lb
