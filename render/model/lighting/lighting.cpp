#include "lighting.h"

#include "lighting_models.h"

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

glm::vec3 lightVector(const glm::vec4 &lightEye, const glm::vec3 &positionEye)
{
    if (lightEye.w == 0.0f)
        return glm::normalize(glm::vec3(lightEye));
    return glm::normalize(glm::vec3(lightEye) - positionEye);
}

glm::vec3 viewVector(const glm::vec3 &positionEye, Projection projection)
{
    if (projection == Projection::Perspective)
        return glm::normalize(-positionEye);
    return glm::vec3(0.0f, 0.0f, 1.0f); // towards a viewer at (0,0,+inf)
}

LightingTerms evaluateLighting(const glm::vec3 &positionEye, const glm::vec3 &normalEye,
                               const LightingInputs &in)
{
    const float distance =
        in.lightEye.w != 0.0f ? glm::length(glm::vec3(in.lightEye) - positionEye) : 0.0f;
    return lightingTerms(lightVector(in.lightEye, positionEye), glm::normalize(normalEye),
                         viewVector(positionEye, in.projection), distance, in);
}

LightingTerms lightingTerms(const glm::vec3 &L, const glm::vec3 &N, const glm::vec3 &V,
                            float distance, const LightingInputs &in)
{
    LightingTerms t;
    t.L = L;
    t.N = N;
    t.V = V;
    t.H = glm::normalize(t.L + t.V);
    // The slides write reflect(L, N), but GLSL's reflect(I, N) mirrors an *incident* direction
    // I (pointing at the surface). L points away from the surface, so the mirror of the light
    // ray is reflect(-L, N) = 2(N·L)N - L, which points away from the surface as R must.
    t.R = glm::reflect(-t.L, t.N);

    t.nDotL = glm::dot(t.L, t.N);
    t.specularAngle = specularModel(in.specular).cosine(t);
    const Material &m = in.material;
    t.specularFactor = glm::pow(glm::max(t.specularAngle, 0.0f), m.shininess);
    if (t.nDotL < 0.0f) // light hits the back of the surface: no highlight (slides)
        t.specularFactor = 0.0f;

    if (in.lightEye.w != 0.0f)
        t.distance = distance;
    t.attenuation = attenuationFactor(in.lightEye, t.distance, in.attenuation);
    t.spot = spotFactor(t.L, in.spotDirectionEye, in.spotCosCutoff, in.spotExponent);
    // OpenGL 2.1's fixed-function equation: attenuation and spot scale all three terms.
    const float scale = t.attenuation * t.spot;
    t.ambient = scale * (in.colors.ia * m.ka);
    t.diffuse = scale * (diffuseFactor(t.nDotL) * (in.colors.id * m.kd)); // none from behind
    t.specular = scale * (t.specularFactor * (in.colors.is * m.ks));
    return t;
}

float degreesFromCosine(float cosine)
{
    return glm::degrees(std::acos(std::clamp(cosine, -1.0f, 1.0f)));
}

float attenuationFactor(const glm::vec4 &lightEye, float distance, const glm::vec3 &k)
{
    if (lightEye.w == 0.0f)
        return 1.0f;
    return 1.0f / glm::max(k.x + k.y * distance + k.z * distance * distance, 1e-6f);
}

float spotFactor(const glm::vec3 &L, const glm::vec3 &D, float cosCutoff, float exponent)
{
    if (cosCutoff <= -1.0f)
        return 1.0f;
    const float cosAngle = glm::dot(-L, D);
    if (cosAngle < cosCutoff)
        return 0.0f;
    // 0^0 is 1 here, as in OpenGL's equation; GLSL's pow() leaves it undefined, so the
    // shaders test for exponent 0 the same way.
    return exponent == 0.0f ? 1.0f : glm::pow(glm::max(cosAngle, 0.0f), exponent);
}

glm::vec3 shownColor(ShowChoice show, const LightingTerms &t)
{
    const auto asColour = [](const glm::vec3 &v) { return 0.5f * v + 0.5f; };
    switch (show) {
    case ShowChoice::Colour:
        break;
    case ShowChoice::Normal:
        return asColour(t.N);
    case ShowChoice::Light:
        return asColour(t.L);
    case ShowChoice::View:
        return asColour(t.V);
    case ShowChoice::Half:
        return asColour(t.H);
    case ShowChoice::Reflect:
        return asColour(t.R);
    case ShowChoice::NDotL:
        return glm::vec3(t.nDotL); // negative (light behind) shows black
    case ShowChoice::Specular:
        return glm::vec3(t.specularFactor);
    case ShowChoice::Attenuation:
        return glm::vec3(t.attenuation);
    }
    return glm::vec3(0.0f);
}

glm::vec3 shadedColor(const glm::vec3 &ambientPlusDiffuse, const glm::vec3 &specular,
                      const glm::vec3 &base)
{
    return base * ambientPlusDiffuse + specular;
}

glm::vec3 unlitColor(const Material &material, const glm::vec3 &base)
{
    return material.kd * base;
}

} // namespace lb
