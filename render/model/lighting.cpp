#include "lighting.h"

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

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
    LightingTerms t;
    t.L = lightVector(in.lightEye, positionEye);
    t.N = glm::normalize(normalEye);
    t.V = viewVector(positionEye, in.projection);
    t.H = glm::normalize(t.L + t.V);
    // The slides write reflect(L, N), but GLSL's reflect(I, N) mirrors an *incident* direction
    // I (pointing at the surface). L points away from the surface, so the mirror of the light
    // ray is reflect(-L, N) = 2(N·L)N - L, which points away from the surface as R must.
    t.R = glm::reflect(-t.L, t.N);

    t.nDotL = glm::dot(t.L, t.N);
    t.specularAngle = in.specular == SpecularModel::Blinn ? glm::dot(t.N, t.H) : glm::dot(t.R, t.V);

    const Material &m = in.material;
    t.ambient = in.colors.ia * m.ka;
    t.diffuse = glm::max(t.nDotL, 0.0f) * (in.colors.id * m.kd); // no light from behind
    const float specularFactor = glm::pow(glm::max(t.specularAngle, 0.0f), m.shininess);
    t.specular = specularFactor * (in.colors.is * m.ks);
    if (t.nDotL < 0.0f) // light hits the back of the surface: no highlight (slides)
        t.specular = glm::vec3(0.0f);
    return t;
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
