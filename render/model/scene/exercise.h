#pragma once
// An exercise: a scene file with a task for the student, the reference program (the teacher's
// solution, or the built-in program with given switches) and how a student's program is
// graded: how many cases, which of the scene's parameters each case varies, the frame size
// and the tolerance per pixel. The scene file's own program is the student's starting point.
//
// In a scene file, the "exercise" object:
//   {"title": "...", "task": "...",     (or {"en": "...", "pt": "...", "de": "..."}, each)
//    "reference": {"vertex": "...", "fragment": "..."}            (the teacher's solution)
//             or {"builtIn": {"shading": "phong", "specular": "phong"}},
//    "grading": {"cases": 20, "size": [320, 240], "tolerance": 2, "passShare": 0.99,
//                "vary": ["light", "lightW", "lightFrame", "lightColour", "material",
//                         "camera", "projection", "scale"],
//                "points": 100,      (the total in equal shares, or [p0, p1, ...]: one per case)
//                "frameBudget": 2},  (seconds one frame at "size" may take, program_trial.h)
//    "mistakes": [...]}                 (known mistakes and their hints: exercise_mistakes.h)

#include "exercise_mistakes.h"
#include "localized_text.h"
#include "scene.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QSize>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace lb {

// What the cases of an exercise vary (light 1 and every object), each a bit.
enum class Vary : unsigned {
    Light = 1u << 0,       // light 1's position (kept 2 to 4 units from the origin)
    LightW = 1u << 1,      // point (w = 1) or directional (w = 0)
    LightFrame = 1u << 2,  // camera, world or object frame
    LightColour = 1u << 3, // Ia, Id, Is
    Material = 1u << 4,    // Ka, Kd, Ks and shininess
    Camera = 1u << 5,      // the orbit's yaw and pitch
    Projection = 1u << 6,  // perspective or orthographic
    Scale = 1u << 7,       // a non-uniform scale and a rotation: a wrong normal matrix shows
};
constexpr unsigned kVaryAll = (1u << 8) - 1;
QStringList varyNames(); // as the file names them, in the order above

struct ExerciseReference
{
    // The teacher's solution; absent: the built-in program with these choices.
    QString vertex, fragment;
    Shading shading = Shading::Phong;
    SpecularModel specular = SpecularModel::Phong;
    bool builtIn() const { return vertex.isEmpty(); }
};

struct GradingSpec
{
    int cases = 20; // case 0 is the exercise's scene as it is
    QSize size{320, 240};
    int tolerance = 2;       // per channel, out of 255
    double passShare = 0.99; // a case passes when this share of its pixels is within tolerance
    unsigned vary = kVaryAll;
    // What the cases are worth: `points` in equal shares, unless `casePoints` gives each
    // case's own (then it has one per case). A submission scores the points of its passed cases.
    double points = 100.0;
    std::vector<double> casePoints;
    // What one frame at `size` may cost a submission (and the reference, and each known
    // mistake), in seconds: processor time where a software rasterizer draws, so that the
    // machine's load does not move it (Renderer::renderTimed). A teacher whose exercise asks
    // for heavy work raises it.
    double frameBudget = 2.0;
    double frameBudgetMs() const { return frameBudget * 1000.0; }
};
// The range of GradingSpec::frameBudget and of --frame-budget.
constexpr double kMinFrameBudget = 0.01, kMaxFrameBudget = 60.0;
// The points of each case, `spec.cases` of them.
std::vector<double> pointsPerCase(const GradingSpec &spec);

struct Exercise
{
    LocalizedText title, task; // shown in the window's language (localized_text.h)
    ExerciseReference reference;
    GradingSpec grading;
    std::vector<ExerciseMistake> mistakes; // what a failing submission's frames may match
    // A section that cannot be graded against (no reference yet, while the teacher writes
    // it) is kept as it was read and written back so; set only then.
    QJsonValue unread{QJsonValue::Undefined};
};

QJsonObject exerciseJson(const Exercise &exercise);
// Fields it cannot use keep their defaults and are named in `ignored` ("exercise.grading.
// cases (out of range, clamped)"); a reference that is neither a program nor a built-in
// choice, or a missing one, is an error: nothing to grade against (the exercise then holds
// the section as `unread`, so that saving the scene keeps it).
struct ExerciseRead
{
    std::optional<Exercise> exercise;
    QString error;
};
ExerciseRead readExercise(const QJsonValue &json, QStringList *ignored);

// The scenes of the cases, from `base`: case 0 is `base`, each other one varies what
// `spec.vary` names, drawn from `seed` and its index alone (the same seed gives the same
// cases, and case 3 is the same whether 5 or 20 are asked for).
std::vector<Scene> gradingCases(const Scene &base, const GradingSpec &spec, std::uint32_t seed);
// A case as the reference draws it: a built-in reference's shading and specular choices set
// (a program reference draws the case as it is).
Scene referenceCase(const Scene &caseScene, const ExerciseReference &reference);

} // namespace lb
