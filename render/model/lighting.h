#pragma once
// CPU reference of the course's lighting model (slides "Iluminação e Sombreamento - WebGL").
// Everything is evaluated in the camera (eye) frame, as the slides do. This is the single source
// of truth: the built-in shaders in shaders/ implement the same formulas, and the tests compare
// the GPU's pixels against these functions.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace lb {

enum class SpecularModel { Phong, Blinn }; // R·V (Phong) or N·H (Blinn-Phong)
enum class Projection { Perspective, Orthographic };

struct Material
{
    glm::vec3 ka{1.0f, 0.0f, 0.0f}; // slides: materialAmb
    glm::vec3 kd{1.0f, 0.0f, 0.0f}; // materialDif
    glm::vec3 ks{1.0f, 1.0f, 1.0f}; // materialSpe
    float shininess = 6.0f;
};

struct LightColors
{
    glm::vec3 ia{0.2f}; // slides: lightAmb
    glm::vec3 id{0.7f}; // lightDif
    glm::vec3 is{1.0f}; // lightSpe
};

// The vectors and terms of the model at one surface point, all in eye coordinates.
struct LightingTerms
{
    glm::vec3 L{0.0f}, N{0.0f}, V{0.0f}, H{0.0f}, R{0.0f};
    float nDotL = 0.0f;
    float specularAngle = 0.0f; // N·H for Blinn-Phong, R·V for Phong (before clamping)
    glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};
};

struct LightingInputs
{
    glm::vec4 lightEye{0.0f, 0.0f, 1.0f, 0.0f}; // w = 0 direction towards the light, w = 1 point
    Material material;
    LightColors colors;
    SpecularModel specular = SpecularModel::Blinn;
    Projection projection = Projection::Perspective;
};

// L: towards the light. Directional (w = 0): the light's direction; point: light - P.
glm::vec3 lightVector(const glm::vec4 &lightEye, const glm::vec3 &positionEye);
// V: towards the viewer. Perspective: -posC (eye at the origin); parallel: (0,0,1).
glm::vec3 viewVector(const glm::vec3 &positionEye, Projection projection);

// Evaluates the model at a point with the given (not necessarily unit) normal.
LightingTerms evaluateLighting(const glm::vec3 &positionEye, const glm::vec3 &normalEye,
                               const LightingInputs &in);

// Lights add up: the sum of the ambient, diffuse and specular terms of each light.
struct LightingSum
{
    glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};
    LightingSum &operator+=(const LightingTerms &t)
    {
        ambient += t.ambient;
        diffuse += t.diffuse;
        specular += t.specular;
        return *this;
    }
};

// The colour the model gives, before the framebuffer clamps it: the base colour (vertex colour
// and/or texture, white when off) modulates ambient and diffuse; specular is the light's own.
glm::vec3 shadedColor(const glm::vec3 &ambientPlusDiffuse, const glm::vec3 &specular,
                      const glm::vec3 &base);
// With lighting switched off the surface shows its diffuse colour times the base colour.
glm::vec3 unlitColor(const Material &material, const glm::vec3 &base);

} // namespace lb
