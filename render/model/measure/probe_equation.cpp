#include "probe_equation.h"

#include <glm/common.hpp>

#include <cmath>

namespace lb {

namespace {

QString number(float v)
{
    return QString::number(double(v), 'f', 4);
}

QString triple(const glm::vec3 &v)
{
    return QString("(%1, %2, %3)").arg(number(v.x), number(v.y), number(v.z));
}

} // namespace

QString lightingEquation(const Scene &scene, const ProbeResult &probe)
{
    if (!probe.hit)
        return {};
    const TermSwitches &on = scene.shading.terms;
    const QString angle = QString::fromUtf8(specularModel(scene.shading.specular).angle);
    const float n = scene.objects[std::size_t(probe.object)].material.shininess;

    // In symbols: OpenGL 2.1's fixed-function form, attenuation and spot scaling all three.
    QStringList symbols;
    if (on.ambient)
        symbols << "Ia·Ka";
    if (on.diffuse)
        symbols << "Id·Kd·max(N·L, 0)";
    if (on.specular)
        symbols << QString("Is·Ks·max(%1, 0)^n").arg(angle);
    const bool base = probe.base != glm::vec3(1.0f);
    QStringList lines;
    lines << QString("I = %1Σ att·spot·(%2)%3")
                 .arg(base ? "base·" : "", symbols.isEmpty() ? "0" : symbols.join(" + "),
                      base && on.specular ? "   (base multiplies ambient and diffuse only)" : "");

    for (const ProbeLight &light : probe.lights) {
        const LightingTerms &t = light.terms;
        const LightColors &c = light.inputs.colors;
        const Material &m = light.inputs.material;
        lines << QString("light %1: att·spot = %2·%3 = %4%5")
                     .arg(light.index + 1)
                     .arg(number(t.attenuation), number(t.spot), number(t.attenuation * t.spot),
                          light.inputs.lightEye.w != 0.0f
                              ? QString(" (d = %1)").arg(number(t.distance))
                              : QString());
        const auto term = [&](bool enabled, const QString &text, const glm::vec3 &value) {
            lines << QString("  %1%2 = %3").arg(enabled ? "" : "[off] ", text, triple(value));
        };
        term(on.ambient,
             QString("att·spot·Ia·Ka = %1·%2·%3")
                 .arg(number(t.attenuation * t.spot), triple(c.ia), triple(m.ka)),
             t.ambient);
        term(on.diffuse,
             QString("att·spot·Id·Kd·max(N·L, 0) = %1·%2·%3·%4")
                 .arg(number(t.attenuation * t.spot), triple(c.id), triple(m.kd),
                      number(std::max(t.nDotL, 0.0f))),
             t.diffuse);
        term(on.specular,
             QString("att·spot·Is·Ks·max(%1, 0)^n = %2·%3·%4·%5^%6%7")
                 .arg(angle, number(t.attenuation * t.spot), triple(c.is), triple(m.ks),
                      number(std::max(t.specularAngle, 0.0f)), QString::number(double(n)),
                      t.nDotL < 0.0f ? " (0: the light is behind the surface)" : ""),
             t.specular);
    }
    const LightingSum &s = probe.total;
    const glm::vec3 sum = shadedColor(s.ambient + s.diffuse, s.specular, probe.base);
    lines << QString("I = %1%2 + %3 = %4")
                 .arg(base ? triple(probe.base) + "·" : "",
                      base ? "(" + triple(s.ambient + s.diffuse) + ")"
                           : triple(s.ambient + s.diffuse),
                      triple(s.specular), triple(sum));
    const glm::vec3 clamped = glm::clamp(sum, 0.0f, 1.0f);
    lines << QString("pixel = %1 of 255 (clamped to 0..1)")
                 .arg(QString("(%1, %2, %3)")
                          .arg(std::lround(clamped.r * 255.0f))
                          .arg(std::lround(clamped.g * 255.0f))
                          .arg(std::lround(clamped.b * 255.0f)));
    if (!scene.shading.lighting)
        lines << "Lighting is off: the surface shows Kd times the base colour instead.";
    if (scene.shading.shading == Shading::Flat)
        lines << "Flat shading draws the model at the triangle's last (provoking) vertex, one "
                 "colour for the triangle; these numbers are the model at this point.";
    if (scene.shading.shading == Shading::Gouraud)
        lines << "Gouraud shading draws the model at the triangle's vertices, interpolated; "
                 "these numbers are the model at this point.";
    if (scene.shading.show != ShowChoice::Colour)
        lines << QString("The surface shows %1, not this colour.").arg(toName(scene.shading.show));
    return lines.join('\n');
}

} // namespace lb
