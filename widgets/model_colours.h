#pragma once
// The colours of the model's vectors and terms, one table for the probe's arrows over the
// surface and the Plots panel's curves, so that V is the same cyan in both.

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <QColor>

#include <algorithm>

namespace lb::colours {

constexpr glm::vec3 kNormal{1.0f, 0.85f, 0.25f}; // yellow, as the normal lines
constexpr glm::vec3 kView{0.3f, 0.9f, 1.0f};     // cyan
constexpr glm::vec3 kMirror{1.0f, 0.35f, 1.0f};  // magenta: R (Phong) or H (Blinn-Phong)
// The terms: ambient a slate blue, diffuse a warm orange, specular the mirror's magenta (its
// peak lies along R).
constexpr glm::vec3 kAmbient{0.55f, 0.62f, 0.85f};
constexpr glm::vec3 kDiffuse{1.0f, 0.55f, 0.2f};
constexpr glm::vec3 kSpecular = kMirror;
// Each specular model's curves have its own colour (SpecularModelRow::curveColour).

// L's arrow: the light's diffuse colour at full brightness, never darker than 0.3 (a dark
// light's arrow stays visible).
inline glm::vec3 lightArrow(const glm::vec3 &diffuse)
{
    const float peak = std::max({diffuse.r, diffuse.g, diffuse.b, 1e-3f});
    return glm::max(diffuse / peak, glm::vec3(0.3f));
}

inline QColor toQColor(const glm::vec3 &c)
{
    return QColor::fromRgbF(c.r, c.g, c.b);
}

} // namespace lb::colours
