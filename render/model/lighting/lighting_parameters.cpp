#include "lighting_parameters.h"

#include <QCoreApplication>

#include <glm/geometric.hpp>

#include <cstring>

namespace lb {

namespace {

const char *refusePosition(const float *v)
{
    if (v[3] != 0.0f && v[3] != 1.0f)
        return QT_TRANSLATE_NOOP("lb::LightingParameters",
                                 "w must be 0 (directional) or 1 (point)");
    if (v[3] == 0.0f && v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f)
        return QT_TRANSLATE_NOOP("lb::LightingParameters",
                                 "a directional light (w = 0) with the direction 0, 0, 0");
    return nullptr;
}

const char *refuseAttenuation(const float *v)
{
    if (v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f)
        return QT_TRANSLATE_NOOP("lb::LightingParameters",
                                 "kc, kl and kq all 0 (the light would be infinite)");
    return nullptr;
}

const char *refuseAxis(const float *v)
{
    if (glm::length(glm::vec3(v[0], v[1], v[2])) < limits::kMinDirectionLength)
        return QT_TRANSLATE_NOOP("lb::LightingParameters", "a direction of length 0");
    return nullptr;
}

constexpr float kC = limits::kMaxCoordinate;

} // namespace

const std::vector<LightingParameter> &lightingParameters()
{
    using O = ParameterOwner;
    using S = Semantic;
    static const std::vector<LightingParameter> rows{
        {O::Light,
         "position",
         "light",
         "X,Y,Z,W",
         4,
         -kC,
         kC,
         2,
         0.1,
         "x y z w",
         "Light position (W = 1) or direction towards the light (W = 0), in its frame",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "lightPosition.%1: the light's %1 in the chosen frame"),
         "light.position",
         {S::LightPosition, S::LightPositionEye},
         [](Light &l) { return &l.position.x; },
         nullptr,
         refusePosition},
        {O::Light,
         "ia",
         "ia",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Ia",
         "Ambient intensity of the light, Ia",
         //: %1 the symbol (Ia, Id, Is); %2 the uniforms that carry it
         QT_TRANSLATE_NOOP("lb::LightingParameters", "%1 (%2): the light's ambient intensity"),
         "light.colours",
         {S::LightAmbient},
         [](Light &l) { return &l.colors.ia.x; },
         nullptr,
         nullptr},
        {O::Light,
         "id",
         "id",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Id",
         "Diffuse intensity of the light, Id",
         QT_TRANSLATE_NOOP("lb::LightingParameters", "%1 (%2): the light's diffuse intensity"),
         "light.colours",
         {S::LightDiffuse},
         [](Light &l) { return &l.colors.id.x; },
         nullptr,
         nullptr},
        {O::Light,
         "is",
         "is",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Is",
         "Specular intensity of the light, Is",
         QT_TRANSLATE_NOOP("lb::LightingParameters", "%1 (%2): the light's specular intensity"),
         "light.colours",
         {S::LightSpecular},
         [](Light &l) { return &l.colors.is.x; },
         nullptr,
         nullptr},
        {O::Light,
         "attenuation",
         "attenuation",
         "KC,KL,KQ",
         3,
         0.0f,
         limits::kMaxAttenuation,
         2,
         0.05,
         "kc kl kq",
         "Attenuation of light 1 when it is a point, 1 / (KC + KL*d + KQ*d^2); not all 0, and "
         "1,0,0 is none",
         //: %1 the axis (x, y, z); %2 its name (kc, kl, kq)
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "lightAttenuation.%1 (%2): a point light's terms are divided by kc + "
                           "kl·d + kq·d², d its distance to the surface (1, 0, 0: none; a "
                           "directional light is never attenuated)"),
         nullptr,
         {S::LightAttenuation},
         [](Light &l) { return &l.attenuation.x; },
         nullptr,
         refuseAttenuation},
        {O::Light,
         "spot.direction",
         nullptr,
         "DX,DY,DZ",
         3,
         -kC,
         kC,
         2,
         0.1,
         "D",
         "The spotlight's axis, from the light, in the light's frame",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "spotDirection.%1: the spotlight's axis, from the light, in the "
                           "light's frame"),
         nullptr,
         {S::SpotDirection},
         [](Light &l) { return &l.spot.direction.x; },
         nullptr,
         refuseAxis},
        {O::Light,
         "spot.cutoff",
         nullptr,
         "CUTOFF",
         1,
         0.0f,
         limits::kMaxSpotCutoff,
         1,
         1.0,
         "cutoff",
         "The spotlight cone's half-angle in degrees (180: no spot)",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "spotCutoff: the cone's half-angle; outside it the light adds "
                           "nothing, ambient included (180: no spot)"),
         nullptr,
         {S::SpotCutoff, S::SpotCosCutoff},
         [](Light &l) { return &l.spot.cutoffDegrees; },
         nullptr,
         nullptr},
        {O::Light,
         "spot.exponent",
         nullptr,
         "EXPONENT",
         1,
         0.0f,
         limits::kMaxSpotExponent,
         1,
         1.0,
         "exp",
         "The spotlight's exponent: brighter towards its axis",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "spotExponent: inside the cone the terms are scaled by "
                           "max(-L·D, 0)^exponent, brighter towards the axis"),
         nullptr,
         {S::SpotExponent},
         [](Light &l) { return &l.spot.exponent; },
         nullptr,
         nullptr},
        {O::Material,
         "ka",
         "ka",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Ka",
         "Ambient reflection of the material, Ka",
         //: %1 the symbol (Ka, Kd, Ks); %2 the uniforms that carry it
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "%1 (%2): the material's ambient reflection coefficients"),
         "material",
         {S::MaterialAmbient},
         nullptr,
         [](Material &m) { return &m.ka.x; },
         nullptr},
        {O::Material,
         "kd",
         "kd",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Kd",
         "Diffuse reflection of the material, Kd",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "%1 (%2): the material's diffuse reflection coefficients"),
         "material",
         {S::MaterialDiffuse},
         nullptr,
         [](Material &m) { return &m.kd.x; },
         nullptr},
        {O::Material,
         "ks",
         "ks",
         "R,G,B",
         3,
         0.0f,
         1.0f,
         2,
         0.05,
         "Ks",
         "Specular reflection of the material, Ks",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "%1 (%2): the material's specular reflection coefficients"),
         "material",
         {S::MaterialSpecular},
         nullptr,
         [](Material &m) { return &m.ks.x; },
         nullptr},
        {O::Material,
         "shininess",
         "shininess",
         "S",
         1,
         limits::kMinShininess,
         limits::kMaxShininess,
         1,
         1.0,
         "n",
         "Specular exponent",
         QT_TRANSLATE_NOOP("lb::LightingParameters",
                           "shininess: the specular exponent n in (R.V)^n or (N.H)^n; higher "
                           "gives a smaller, sharper highlight"),
         "material.shininess",
         {S::Shininess},
         nullptr,
         [](Material &m) { return &m.shininess; },
         nullptr},
    };
    return rows;
}

std::vector<const LightingParameter *> lightingParameters(ParameterOwner owner)
{
    std::vector<const LightingParameter *> of;
    for (const LightingParameter &p : lightingParameters())
        if (p.owner == owner)
            of.push_back(&p);
    return of;
}

const LightingParameter *lightingParameter(ParameterOwner owner, const char *key)
{
    for (const LightingParameter &p : lightingParameters())
        if (p.owner == owner && std::strcmp(p.key, key) == 0)
            return &p;
    return nullptr;
}

QString LightingParameter::toolTipText() const
{
    return QCoreApplication::translate("lb::LightingParameters", tooltip);
}

QString LightingParameter::refusal(const float *v) const
{
    const char *why = refuse ? refuse(v) : nullptr;
    return why ? QCoreApplication::translate("lb::LightingParameters", why) : QString();
}

QString LightingParameter::refusalInEnglish(const float *v) const
{
    const char *why = refuse ? refuse(v) : nullptr;
    return why ? QString::fromUtf8(why) : QString();
}

namespace {

template <typename Owner> bool sameNumbers(ParameterOwner owner, const Owner &a, const Owner &b)
{
    for (const LightingParameter *p : lightingParameters(owner))
        if (!std::equal(p->numbers(a), p->numbers(a) + p->count, p->numbers(b)))
            return false;
    return true;
}

} // namespace

bool sameParameters(const Light &a, const Light &b)
{
    return sameNumbers(ParameterOwner::Light, a, b);
}

bool sameParameters(const Material &a, const Material &b)
{
    return sameNumbers(ParameterOwner::Material, a, b);
}

} // namespace lb
