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

// What the surface shows: the lit colour, or one of the model's vectors (as 0.5·v + 0.5) or
// numbers (as grey) at each point. L, H, R, N·L, the specular factor and the attenuation are
// light 1's.
enum class ShowChoice { Colour, Normal, Light, View, Half, Reflect, NDotL, Specular, Attenuation };

// The three terms of the model, each of which can be switched off to see the others alone.
struct TermSwitches
{
    bool ambient = true;
    bool diffuse = true;
    bool specular = true;
};

// A spotlight, as OpenGL 2.1's fixed-function lights have it: the cone's axis (from the light,
// in the light's own frame), its half-angle in degrees (180: no spot, light in every
// direction) and how sharply the light falls off towards the cone's edge.
struct Spot
{
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float cutoffDegrees = 180.0f;
    float exponent = 0.0f;
};

// The vectors and terms of the model at one surface point, all in eye coordinates.
struct LightingTerms
{
    glm::vec3 L{0.0f}, N{0.0f}, V{0.0f}, H{0.0f}, R{0.0f};
    float nDotL = 0.0f;
    float specularAngle = 0.0f;  // N·H for Blinn-Phong, R·V for Phong (before clamping)
    float specularFactor = 0.0f; // max(specularAngle, 0)^n, 0 where the light is behind
    float distance = 0.0f;       // from the point to a point light (0 for a directional one)
    float attenuation = 1.0f;    // 1 / (kc + kl·d + kq·d²); 1 for a directional light
    float spot = 1.0f;           // 0 outside the cone, max(-L·D, 0)^exponent inside
    // Each already multiplied by attenuation·spot; switched-off terms are still computed here
    // (the probe shows them) and left out by LightingSum.
    glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};
};

struct LightingInputs
{
    glm::vec4 lightEye{0.0f, 0.0f, 1.0f, 0.0f}; // w = 0 direction towards the light, w = 1 point
    Material material;
    LightColors colors;
    SpecularModel specular = SpecularModel::Blinn;
    Projection projection = Projection::Perspective;
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f}; // kc, kl, kq
    glm::vec3 spotDirectionEye{0.0f, 0.0f, -1.0f};
    float spotCosCutoff = -1.0f; // cos(cutoff); -1 (180 degrees): no spot
    float spotExponent = 0.0f;
};

// 1 / (kc + kl·d + kq·d²) for a point light at distance d (the denominator kept above 1e-6
// so that a light on the surface with kc = 0 gives a bright point, not infinity); 1 for a
// directional light (w = 0).
float attenuationFactor(const glm::vec4 &lightEye, float distance, const glm::vec3 &k);
// 0 outside the cone (-L·D below cosCutoff), max(-L·D, 0)^exponent inside; 1 with no spot
// (cosCutoff <= -1). L towards the light, D the cone's axis; both unit length.
float spotFactor(const glm::vec3 &L, const glm::vec3 &D, float cosCutoff, float exponent);

// L: towards the light. Directional (w = 0): the light's direction; point: light - P.
glm::vec3 lightVector(const glm::vec4 &lightEye, const glm::vec3 &positionEye);
// V: towards the viewer. Perspective: -posC (eye at the origin); parallel: (0,0,1).
glm::vec3 viewVector(const glm::vec3 &positionEye, Projection projection);

// Evaluates the model at a point with the given (not necessarily unit) normal.
LightingTerms evaluateLighting(const glm::vec3 &positionEye, const glm::vec3 &normalEye,
                               const LightingInputs &in);
// The same once the vectors are known: unit L (towards the light), N and V (towards the
// viewer), and the distance to a point light (ignored for a directional one). The plots sweep
// one of the vectors through it (plots.h).
LightingTerms lightingTerms(const glm::vec3 &L, const glm::vec3 &N, const glm::vec3 &V,
                            float distance, const LightingInputs &in);
// The angle in degrees whose cosine is `cosine` (clamped to [-1, 1] first): the plots' x.
float degreesFromCosine(float cosine);
// The diffuse factor max(N·L, 0): no light from behind. As glm::max(nDotL, 0.0f) is (a NaN
// passes through), so evaluateLighting gives what it gave before the plots shared it.
inline float diffuseFactor(float nDotL)
{
    return nDotL < 0.0f ? 0.0f : nDotL;
}

// Lights add up: the sum of the ambient, diffuse and specular terms of each light, of the
// terms switched on.
struct LightingSum
{
    glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};
    void add(const LightingTerms &t, const TermSwitches &on)
    {
        if (on.ambient)
            ambient += t.ambient;
        if (on.diffuse)
            diffuse += t.diffuse;
        if (on.specular)
            specular += t.specular;
    }
};

// The colour the model gives, before the framebuffer clamps it: the base colour (vertex colour
// and/or texture, white when off) modulates ambient and diffuse; specular is the light's own.
// The colour `show` gives at a point where light 1's terms are `light1` (ShowChoice::Colour:
// none; the caller uses the lit colour).
glm::vec3 shownColor(ShowChoice show, const LightingTerms &light1);

glm::vec3 shadedColor(const glm::vec3 &ambientPlusDiffuse, const glm::vec3 &specular,
                      const glm::vec3 &base);
// With lighting switched off the surface shows its diffuse colour times the base colour.
glm::vec3 unlitColor(const Material &material, const glm::vec3 &base);

} // namespace lb
