#pragma once
// The lighting model's numbers declared once: one row per number (or vector) of a light or a
// material. The scene's JSON reader and writer, its equality, the command line, the panels'
// boxes and the lessons' highlights loop over these rows; a new parameter is a row here, its
// member in Light or Material, its use in the lighting math and the shaders, and a test.

#include "light.h"
#include "lighting.h"
#include "semantics.h"

#include <QString>

#include <vector>

namespace lb {

// Limits shared by the panels, the files and the command line.
namespace limits {
constexpr float kMinShininess = 1.0f;
constexpr float kMaxShininess = 1000.0f;
constexpr float kMaxCoordinate = 1000.0f;    // light positions, translations, the camera
constexpr float kMaxAttenuation = 1000.0f;   // each of kc, kl, kq, at least 0; not all 0
constexpr float kMaxSpotCutoff = 180.0f;     // degrees; 180: no spot
constexpr float kMaxSpotExponent = 128.0f;   // as OpenGL 2.1 allows
constexpr float kMinDirectionLength = 1e-6f; // shorter spot axes are refused (normalize fails)
} // namespace limits

enum class ParameterOwner { Light, Material };

struct LightingParameter
{
    ParameterOwner owner;
    // Its key in the owner's JSON object; "spot.cutoff" lies in the object under "spot".
    const char *key;
    const char *option;  // the command line's option (light 1's, the selected object's)
    const char *metavar; // how the option's value is written: "R,G,B"
    int count;           // how many numbers: 1, 3 or 4
    float lo, hi;        // each number's range
    int decimals;        // the panel's boxes
    double step;
    const char *symbol; // as the panel's rows and the equation write it: "Ia", "kc kl kq"
    // What it is, in English, for the command line's help and man page; its range follows.
    const char *description;
    // The panel's tooltip (translated in the context lb::LightingParameters); a %1 stands for
    // the axis (x, y, z) where the panel has a box per number.
    const char *tooltip;
    const char *highlight; // the lesson's name of its control ("light.colours")
    // The course's uniforms it feeds (the others' are derived from these: semantics.h).
    std::vector<Semantic> semantics;
    float *(*ofLight)(Light &);       // where its numbers are, for ParameterOwner::Light
    float *(*ofMaterial)(Material &); // for ParameterOwner::Material
    // Why the numbers as a whole cannot be used (QT_TRANSLATE_NOOP in lb::LightingParameters:
    // "kc, kl and kq all 0"), or nullptr: each number in range is not always enough.
    const char *(*refuse)(const float *v);

    float *numbers(Light &light) const { return ofLight(light); }
    const float *numbers(const Light &light) const { return ofLight(const_cast<Light &>(light)); }
    float *numbers(Material &material) const { return ofMaterial(material); }
    const float *numbers(const Material &material) const
    {
        return ofMaterial(const_cast<Material &>(material));
    }
    QString toolTipText() const; // the tooltip, translated, its %1 and %2 left to fill
    // The refusal's reason, translated, or an empty string where the numbers can be used.
    QString refusal(const float *v) const;
    // The reason in English, as the command line writes it.
    QString refusalInEnglish(const float *v) const;
};

const std::vector<LightingParameter> &lightingParameters();
// The rows of one owner, in the table's order.
std::vector<const LightingParameter *> lightingParameters(ParameterOwner owner);
// The row of that owner and key; nullptr for none.
const LightingParameter *lightingParameter(ParameterOwner owner, const char *key);

// Every number of every row equal (the other members are compared by the caller).
bool sameParameters(const Light &a, const Light &b);
bool sameParameters(const Material &a, const Material &b);

} // namespace lb
