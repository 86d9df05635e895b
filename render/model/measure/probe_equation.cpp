#include "probe_equation.h"

#include <QCoreApplication>

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

EquationPart symbols(const QString &text)
{
    return {EquationPart::Kind::Symbols, text};
}

// A phrase where `shown`, else nothing.
EquationPart phrase(bool shown, const char *text, const QString &before = {},
                    const QString &after = {})
{
    if (!shown)
        return {};
    return {EquationPart::Kind::Phrase, QString::fromUtf8(text), before, after};
}

} // namespace

QString fillPattern(const QString &pattern, const QStringList &parts)
{
    QString out;
    for (int i = 0; i < pattern.size(); ++i) {
        const QChar c = pattern[i];
        if (c == '%' && i + 1 < pattern.size() && pattern[i + 1].isDigit() &&
            pattern[i + 1] != '0') {
            const int n = pattern[i + 1].digitValue();
            out += parts.value(n - 1);
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

QString equationLineText(const EquationLine &line)
{
    QStringList parts;
    for (const EquationPart &p : line.parts)
        parts << p.beside(p.text);
    return fillPattern(QString::fromUtf8(line.pattern), parts);
}

std::vector<EquationLine> lightingEquationLines(const Scene &scene, const ProbeResult &probe)
{
    if (!probe.hit)
        return {};
    const TermSwitches &on = scene.shading.terms;
    const QString angle = QString::fromUtf8(specularModel(scene.shading.specular).angle);
    const float n = scene.objects[std::size_t(probe.object)].material.shininess;

    // In symbols: OpenGL 2.1's fixed-function form, attenuation and spot scaling all three.
    QStringList terms;
    if (on.ambient)
        terms << "Ia·Ka";
    if (on.diffuse)
        terms << "Id·Kd·max(N·L, 0)";
    if (on.specular)
        terms << QString("Is·Ks·max(%1, 0)^n").arg(angle);
    const bool base = probe.base != glm::vec3(1.0f);
    std::vector<EquationLine> lines;
    lines.push_back(
        {"I = %1Σ att·spot·(%2)%3",
         {symbols(base ? "base·" : ""), symbols(terms.isEmpty() ? "0" : terms.join(" + ")),
          //: after the equation in symbols, where a texture's base colour multiplies it
          phrase(
              base && on.specular,
              QT_TRANSLATE_NOOP("lb::ProbeEquation", "(base multiplies ambient and diffuse only)"),
              "   ")}});

    for (const ProbeLight &light : probe.lights) {
        const LightingTerms &t = light.terms;
        const LightColors &c = light.inputs.colors;
        const Material &m = light.inputs.material;
        const QString factors =
            QString("att·spot = %1·%2 = %3%4")
                .arg(number(t.attenuation), number(t.spot), number(t.attenuation * t.spot),
                     light.inputs.lightEye.w != 0.0f ? QString(" (d = %1)").arg(number(t.distance))
                                                     : QString());
        //: a light's line of the equation: %1 its number, %2 its factors (att·spot = ...)
        lines.push_back({QT_TRANSLATE_NOOP("lb::ProbeEquation", "light %1: %2"),
                         {symbols(QString::number(light.index + 1)), symbols(factors)},
                         true});
        const auto term = [&](bool enabled, const QString &text, const glm::vec3 &value,
                              bool behind = false) {
            lines.push_back(
                {"  %1%2%3 = %4",
                 {//: before a term the Shading panel switched off
                  phrase(!enabled, QT_TRANSLATE_NOOP("lb::ProbeEquation", "[off]"), {}, " "),
                  symbols(text),
                  //: after the specular term's numbers, where N·L < 0
                  phrase(behind,
                         QT_TRANSLATE_NOOP("lb::ProbeEquation",
                                           "(0: the light is behind the surface)"),
                         " "),
                  symbols(triple(value))}});
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
             QString("att·spot·Is·Ks·max(%1, 0)^n = %2·%3·%4·%5^%6")
                 .arg(angle, number(t.attenuation * t.spot), triple(c.is), triple(m.ks),
                      number(std::max(t.specularAngle, 0.0f)), QString::number(double(n))),
             t.specular, t.nDotL < 0.0f);
    }
    const LightingSum &s = probe.total;
    const glm::vec3 sum = shadedColor(s.ambient + s.diffuse, s.specular, probe.base);
    lines.push_back(
        {"I = %1%2 + %3 = %4",
         {symbols(base ? triple(probe.base) + "·" : ""),
          symbols(base ? "(" + triple(s.ambient + s.diffuse) + ")" : triple(s.ambient + s.diffuse)),
          symbols(triple(s.specular)), symbols(triple(sum))}});
    const glm::vec3 clamped = glm::clamp(sum, 0.0f, 1.0f);
    //: %1 the pixel's red, green and blue, as (r, g, b)
    lines.push_back({QT_TRANSLATE_NOOP("lb::ProbeEquation", "pixel = %1 of 255 (clamped to 0..1)"),
                     {symbols(QString("(%1, %2, %3)")
                                  .arg(std::lround(clamped.r * 255.0f))
                                  .arg(std::lround(clamped.g * 255.0f))
                                  .arg(std::lround(clamped.b * 255.0f)))},
                     true});
    const auto sentence = [&](const char *text) { lines.push_back({text, {}, true}); };
    if (!scene.shading.lighting)
        sentence(QT_TRANSLATE_NOOP(
            "lb::ProbeEquation",
            "Lighting is off: the surface shows Kd times the base colour instead."));
    if (scene.shading.shading == Shading::Flat)
        sentence(QT_TRANSLATE_NOOP(
            "lb::ProbeEquation",
            "Flat shading draws the model at the triangle's last (provoking) vertex, one "
            "colour for the triangle; these numbers are the model at this point."));
    if (scene.shading.shading == Shading::Gouraud)
        sentence(QT_TRANSLATE_NOOP(
            "lb::ProbeEquation",
            "Gouraud shading draws the model at the triangle's vertices, interpolated; these "
            "numbers are the model at this point."));
    if (scene.shading.show != ShowChoice::Colour)
        //: %1 what the Shading panel's Show choice draws instead (normal, ndotl, ...)
        lines.push_back(
            {QT_TRANSLATE_NOOP("lb::ProbeEquation", "The surface shows %1, not this colour."),
             {{EquationPart::Kind::ShowChoice, toName(scene.shading.show)}},
             true});
    return lines;
}

QString lightingEquation(const Scene &scene, const ProbeResult &probe)
{
    QStringList text;
    for (const EquationLine &line : lightingEquationLines(scene, probe))
        text << equationLineText(line);
    return text.join('\n');
}

} // namespace lb
