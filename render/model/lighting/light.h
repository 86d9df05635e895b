#pragma once
// A light of the scene, as the Light panel, the files and the command line give it: where it
// is (in its own frame), its colours, its attenuation and spot. The lighting model's table
// (lighting_parameters.h) names its numbers.

#include "lighting.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace lb {

enum class LightFrame { Camera, World, Object };

struct Light
{
    glm::vec4 position{0.0f, 1.8f, 1.3f, 1.0f}; // the slides' lightPosition; w = 0 or 1
    LightFrame frame = LightFrame::World;       // the slides' complete shaders use world (II)
    LightColors colors;
    bool enabled = true; // a light switched off adds nothing and goes to shaders as black
    // kc, kl, kq of 1 / (kc + kl·d + kq·d²) for a point light; (1, 0, 0): none.
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f};
    Spot spot; // its direction in the light's frame; cutoff 180: none
    // The object whose frame an object-frame light is given in (an index into
    // Scene::objects): the light turns and moves with that object, whichever it lights.
    int object = 0;
};

// Up to four lights add up. Light 1 is the slides' light; a shader that declares one light
// (lightPosition, not lightPosition[4]) reads light 1.
constexpr int kMaxLights = 4;
using Lights = std::array<Light, kMaxLights>;
// Light 1 on with the slides' values; 2 to 4 off, placed and coloured so that switching one
// on shows where it is (no ambient of their own: one ambient term is the slides' model).
Lights defaultLights();

} // namespace lb
