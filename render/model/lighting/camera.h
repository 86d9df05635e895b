#pragma once
// Orbit camera: it circles a target at a distance; yaw turns around world Y, pitch tilts up.

#include "lighting.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace lb {

struct OrbitCamera
{
    glm::vec3 target{0.0f};
    float distance = 5.5f;
    float yawDegrees = 25.0f;
    float pitchDegrees = 20.0f;
    static constexpr float kFovYDegrees = 45.0f; // fixed: no control changes it

    glm::vec3 eye() const;
    glm::mat4 view() const; // lookAt(eye, target, up): world -> camera
    // Orthographic uses the view height of the perspective one at the target, so switching
    // projection keeps the object about the same size on screen. Below an aspect of 1 the
    // horizontal field stays that of a square view (the object fits a narrow view's width).
    glm::mat4 projection(float aspect, Projection kind) const;

    void orbit(float dYawDegrees, float dPitchDegrees);
    // In units of the view height, for a view of `aspect`: the target follows the cursor.
    void pan(float dxView, float dyView, float aspect = 1.0f);
    // tan(fovy / 2) of a view of `aspect` (projection() and pan() share it).
    static float tanHalfFovY(float aspect);
    void zoom(float steps); // positive steps move closer
};

} // namespace lb
