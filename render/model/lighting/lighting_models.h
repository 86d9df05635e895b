#pragma once
// The specular models declared once: one row per model, and everything that names, feeds,
// computes, explains or plots a model reads its row. Adding a model is a row here, its
// function in lighting_models.cpp, its branch in shaders/lighting.glsl (SPECULAR_<WORD>, the
// row's uniform value; a test holds the two together) and a test.

#include "lighting.h"

#include <QString>
#include <QStringList>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace lb {

// A curve of the Specular plot: the model's factor against the angle from the mirror
// direction, at the material's exponent times `exponentTimes`.
struct SpecularPlotCurve
{
    const char *key; // the CSV column and the legend's key: "blinn_4n"
    float exponentTimes;
    bool dashed;
};

// A text lupdate finds (QT_TRANSLATE_NOOP3 gives its two parts) and translate() reads.
struct TranslatableText
{
    const char *source;
    const char *comment;
};

struct SpecularModelRow
{
    SpecularModel model;
    const char *word; // in files, on the command line, in presets and plot keys: "phong"
    int uniform;      // uSpecularModel's value: SPECULAR_<WORD> in shaders/lighting.glsl
    const char *name; // the model's proper name, the same in every language: "Blinn-Phong"
    // The word a sentence names it by, translated in lb::ChoiceLabels: "blinn" in "gouraud
    // shading, blinn specular".
    TranslatableText label;
    const char *angle;    // the cosine the exponent raises, as the equation writes it: "N·H"
    const char *angleKey; // the same in JSON output: "NdotH"
    const char *vector;   // the vector it takes beside N or V, drawn by the probe: "H"
    const char *factor;   // the factor in symbols, as the Shading panel shows it: "(N·H)^n"
    glm::vec3 LightingTerms::*vectorOf;
    // The cosine from unit vectors towards the light, along the normal and towards the eye,
    // with H = normalize(L + V) and R = reflect(-L, N) given (before clamping).
    float (*cosine)(const LightingTerms &t);
    // In the plane of N and V with L = N: the angle of V from N (degrees) at which the cosine
    // is `c` (the Specular plot puts a probed light's dot there). Phong: acos(c);
    // Blinn-Phong: 2·acos(c), as N·H = cos(angle / 2). None: no place on the curve.
    std::optional<float> (*planeDegrees)(float c);
    std::vector<SpecularPlotCurve> curves;
    glm::vec3 curveColour; // of its curves and dots in the Plots panel
};

const std::vector<SpecularModelRow> &specularModels();
const SpecularModelRow &specularModel(SpecularModel model);
// The model whose curve `key` is (and that curve); nullptr for none.
const SpecularModelRow *specularModelOfCurve(const QString &key,
                                             const SpecularPlotCurve **curve = nullptr);
// The row after `model`'s, the first after the last (Ctrl+B's toggle).
SpecularModel nextSpecularModel(SpecularModel model);

// "Phong (R·V)": the name and its cosine, as captions and status lines write a model.
QString specularModelTitle(SpecularModel model);

// The files' and command line's words.
QString toName(SpecularModel v);
std::optional<SpecularModel> parseSpecularModel(const QString &s);
QStringList specularModelNames();

} // namespace lb
