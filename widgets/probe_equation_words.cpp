#include "probe_equation_words.h"

#include "choice_labels.h"
#include "scene.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace lb {

namespace {

constexpr const char *kContext = "lb::ProbeEquation";

QString translated(const char *source)
{
    return QCoreApplication::translate(kContext, source);
}

// Whole phrases the equation writes, wherever they stand in a line: three sentences under it
// and the remarks in brackets beside its numbers.
const char *const kPhrases[] = {
    QT_TRANSLATE_NOOP("lb::ProbeEquation",
                      "Lighting is off: the surface shows Kd times the base colour instead."),
    QT_TRANSLATE_NOOP("lb::ProbeEquation",
                      "Flat shading draws the model at the triangle's last (provoking) vertex, "
                      "one colour for the triangle; these numbers are the model at this point."),
    QT_TRANSLATE_NOOP("lb::ProbeEquation",
                      "Gouraud shading draws the model at the triangle's vertices, interpolated; "
                      "these numbers are the model at this point."),
    //: after the equation in symbols, where a texture's base colour multiplies it
    QT_TRANSLATE_NOOP("lb::ProbeEquation", "(base multiplies ambient and diffuse only)"),
    //: after the specular term's numbers, where N·L < 0
    QT_TRANSLATE_NOOP("lb::ProbeEquation", "(0: the light is behind the surface)"),
    //: before a term the Shading panel switched off
    QT_TRANSLATE_NOOP("lb::ProbeEquation", "[off]"),
};

// One line with its words translated; the patterns are anchored to the whole line, so a
// sentence is never taken apart.
QString lineForDisplay(QString line)
{
    static const QRegularExpression lightLine(QStringLiteral("^light (\\d+): (.*)$"));
    static const QRegularExpression pixelLine(
        QStringLiteral("^pixel = (\\(.*\\)) of 255 \\(clamped to 0\\.\\.1\\)$"));
    static const QRegularExpression showsLine(
        QStringLiteral("^The surface shows (\\w+), not this colour\\.$"));
    for (const char *phrase : kPhrases)
        line.replace(QLatin1String(phrase), translated(phrase));
    if (const auto m = lightLine.match(line); m.hasMatch())
        //: a light's line of the equation: %1 its number, %2 its factors (att·spot = ...)
        return QCoreApplication::translate("lb::ProbeEquation", "light %1: %2")
            .arg(m.captured(1), m.captured(2));
    if (const auto m = pixelLine.match(line); m.hasMatch())
        //: %1 the pixel's red, green and blue, as (r, g, b)
        return QCoreApplication::translate("lb::ProbeEquation",
                                           "pixel = %1 of 255 (clamped to 0..1)")
            .arg(m.captured(1));
    if (const auto m = showsLine.match(line); m.hasMatch()) {
        const std::optional<ShowChoice> show = parseShowChoice(m.captured(1));
        //: %1 what the Shading panel's Show choice draws instead (normal, ndotl, ...)
        return QCoreApplication::translate("lb::ProbeEquation",
                                           "The surface shows %1, not this colour.")
            .arg(show ? showLabel(*show) : m.captured(1));
    }
    return line;
}

} // namespace

QString equationForDisplay(const QString &equation)
{
    QStringList lines = equation.split('\n');
    for (QString &line : lines)
        line = lineForDisplay(line);
    return lines.join('\n');
}

} // namespace lb
