#include "scene_phrases.h"

#include <QCoreApplication>

#include <utility>

namespace lb {

namespace {

// The translation context of this file's words ("lb::ScenePhrases" in the .ts files).
struct ScenePhrases
{
    Q_DECLARE_TR_FUNCTIONS(lb::ScenePhrases)
};

// The names are the files' words (scene.cpp), marked for lupdate and translated when shown.
// (The shading's and the specular model's names are widgets/choice_labels.h's.)
struct Text
{
    const char *source;
    const char *disambiguation;
};
template <typename E> using Names = std::pair<E, Text>;

// What the built-in program shows instead of the lit colour (the Shading panel's Show).
const Names<ShowChoice> kShowing[] = {
    //: status line: the built-in program draws N as a colour
    {ShowChoice::Normal, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing normal", "show")},
    //: status line: the built-in program draws L (towards the light) as a colour
    {ShowChoice::Light, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing light", "show")},
    //: status line: the built-in program draws V (towards the eye) as a colour
    {ShowChoice::View, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing view", "show")},
    //: status line: the built-in program draws H, the half vector, as a colour
    {ShowChoice::Half, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing half", "show")},
    //: status line: the built-in program draws R, the reflected light, as a colour
    {ShowChoice::Reflect, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing reflect", "show")},
    //: status line: the built-in program draws N·L as grey ("ndotl" is its name in files)
    {ShowChoice::NDotL, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing ndotl", "show")},
    //: status line: the built-in program draws the specular factor as grey
    {ShowChoice::Specular, QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing specular", "show")},
    //: status line: the built-in program draws a point light's attenuation as grey
    {ShowChoice::Attenuation,
     QT_TRANSLATE_NOOP3("lb::ScenePhrases", "showing attenuation", "show")}};

template <typename E, std::size_t N> QString translated(const Names<E> (&names)[N], E value)
{
    for (const auto &[v, text] : names)
        if (v == value)
            return ScenePhrases::tr(text.source, text.disambiguation);
    return toName(value); // a value added to the enum and not yet here: its files' word
}

// One light on: what it is and the frame it is given in, a whole phrase per case.
QString lightPhrase(const Light &light)
{
    const bool directional = light.position.w == 0.0f;
    switch (light.frame) {
    case LightFrame::Camera:
        return directional ? ScenePhrases::tr("directional light in the camera frame")
                           : ScenePhrases::tr("point light in the camera frame");
    case LightFrame::World:
        return directional ? ScenePhrases::tr("directional light in the world frame")
                           : ScenePhrases::tr("point light in the world frame");
    case LightFrame::Object:
        return directional ? ScenePhrases::tr("directional light in the object frame")
                           : ScenePhrases::tr("point light in the object frame");
    }
    return {};
}

} // namespace

QString statusDescription(const Scene &s, const QString &programName, bool builtInProgram,
                          bool readsLight)
{
    // One light: what it is and its frame; several: how many are on.
    int on = 0;
    for (const Light &l : s.lights)
        on += l.enabled ? 1 : 0;
    QString light = ScenePhrases::tr("%n light(s) on", nullptr, on);
    if (!readsLight)
        light = ScenePhrases::tr("the program's own light (marker hidden)");
    else if (on == 1) // the one that is on, whichever it is
        for (const Light &l : s.lights)
            if (l.enabled)
                light = lightPhrase(l);

    // The program, then what the built-in one follows: each clause translated whole, joined
    // in the translator's order and punctuation.
    QStringList clauses{ScenePhrases::tr("Program: %1").arg(programName)};
    if (builtInProgram && s.shading.shading == Shading::Flat)
        clauses << ScenePhrases::tr("drawn flat (per triangle)"); // the same text, FLAT_SHADING 1
    if (builtInProgram && s.shading.show != ShowChoice::Colour)
        clauses << translated(kShowing, s.shading.show);
    if (builtInProgram) // the Shading panel's specular choice applies
        //: %1 the specular model's name and cosine: "Blinn-Phong (N·H)"
        clauses << ScenePhrases::tr("%1 specular").arg(specularModelTitle(s.shading.specular));
    QString program = clauses.takeFirst();
    for (const QString &clause : clauses)
        //: joins the status line's clauses about the program: "Program: toon.vert, drawn flat"
        program = ScenePhrases::tr("%1, %2").arg(program, clause);

    const QString projection = s.shading.projection == Projection::Perspective
                                   ? ScenePhrases::tr("perspective projection")
                                   : ScenePhrases::tr("orthographic projection");
    //: the status line's three places: the program, the light, the projection
    return ScenePhrases::tr("%1  |  %2  |  %3").arg(program, light, projection);
}

} // namespace lb
