#pragma once
// An exercise's known mistakes (issue 33, part 3): each a program that makes one mistake, or
// the built-in program with some switches set wrong. When a submission fails, the grading
// child draws the failing cases with each of them too and, when one matches the student's
// frames far better than the reference does, the reports and Check My Work say its hint.
//
// In the exercise section:
//   "mistakes": [{"name": "normal matrix",
//                 "hint": "..." or {"en": "...", "pt": "...", "de": "..."},
//                 "vertex": "...", "fragment": "..."}          (a stage left out: the
//                                                              reference's, when it has one)
//             or {..., "builtIn": {"shading": "gouraud", "specular": "blinn",
//                                  "terms": {"ambient": false}, "normalsByModelView": true,
//                                  "lightFrame": "world"}}]   (each switch optional)

#include "localized_text.h"
#include "scene.h"

#include <QJsonValue>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace lb {

constexpr int kMaxExerciseMistakes = 16;
constexpr int kMaxMistakeNameCharacters = 200;

// The built-in program's switches a mistake sets; those it leaves unset are the case's own
// (a built-in reference's shading and specular choice included).
struct BuiltInMistake
{
    std::optional<Shading> shading;
    std::optional<SpecularModel> specular;
    std::optional<bool> ambient, diffuse, specularTerm;
    std::optional<bool> normalsByModelView;
    std::optional<LightFrame> lightFrame; // every light's position read in this frame
};

struct ExerciseMistake
{
    QString name;       // short, the reports' data ("normal matrix"); never translated
    LocalizedText hint; // what the student reads: what matches, which cases fail, what to do
    // A program: either stage may be empty (the reference's stage); both empty: built-in.
    QString vertex, fragment;
    BuiltInMistake builtIn;
    bool isBuiltIn() const { return vertex.isEmpty() && fragment.isEmpty(); }
};

// Reads the "mistakes" list. An entry that cannot be used (not an object, past the 16th, no
// name or hint, a program stage that is not text or too long, neither a program nor a
// built-in, a program missing a stage the reference cannot lend) is left out and told to
// `ignore` as "mistakes[3]" or "mistakes[3].vertex" with why; a built-in switch with a bad
// word is left unset and told likewise. `referenceBuiltIn`: the reference lends no stage.
std::vector<ExerciseMistake>
readExerciseMistakes(const QJsonValue &json, bool referenceBuiltIn,
                     const std::function<void(const QString &, const QString &)> &ignore);
// As the file writes it (the reader gives the same list back).
QJsonValue exerciseMistakesJson(const std::vector<ExerciseMistake> &mistakes);

// The mistake's scene for one case: the case with the built-in mistake's switches set (a
// program mistake's case is the case itself).
Scene mistakeScene(const Scene &caseScene, const ExerciseMistake &mistake);

} // namespace lb
