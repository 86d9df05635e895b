#include "exercise.h"

#include "message_text.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace lb {

namespace {

// The translation context of this file's messages.
struct ExerciseMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Exercise)
};

constexpr std::array<const char *, 8> kVaryNames{"light",    "lightW", "lightFrame", "lightColour",
                                                 "material", "camera", "projection", "scale"};
constexpr int kMaxCases = 200;
constexpr int kMaxSide = 2048;
constexpr int kMaxExerciseTextCharacters = 8000; // a title or a task, in one language
// A case's points, or the total: enough for any marking scheme, and far from where sums of
// 200 cases lose whole points to rounding.
constexpr double kMaxPoints = 1e6;

// Uniform in [lo, hi) from the generator's bits, the same with every standard library
// (std::uniform_real_distribution is not specified bit for bit).
class Draw
{
public:
    explicit Draw(std::uint32_t seed) : m_engine(seed) {}
    float uniform(float lo, float hi)
    {
        return lo + (hi - lo) * float(m_engine() >> 8) * (1.0f / 16777216.0f);
    }
    int index(int n) { return std::min(n - 1, int(uniform(0.0f, float(n)))); }
    glm::vec3 colour(float lo, float hi)
    {
        const float r = uniform(lo, hi), g = uniform(lo, hi);
        return {r, g, uniform(lo, hi)};
    }
    // A direction on the unit sphere.
    glm::vec3 direction()
    {
        const float z = uniform(-1.0f, 1.0f), a = uniform(0.0f, 6.2831853f);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        return {r * std::cos(a), r * std::sin(a), z};
    }

private:
    std::mt19937 m_engine;
};

QString text(const QJsonObject &o, const char *key)
{
    return o.value(QLatin1String(key)).toString();
}

// "points": a total in equal shares, or one per case (read after "cases": the list must have
// as many). What cannot be used keeps the default, 100 in equal shares, and is named.
template <typename Ignore>
void readPoints(const QJsonValue &json, GradingSpec &spec, const Ignore &ignore)
{
    const auto usable = [](const QJsonValue &v) {
        return v.isDouble() && std::isfinite(v.toDouble()) && v.toDouble() >= 0.0 &&
               v.toDouble() <= kMaxPoints;
    };
    if (json.isUndefined())
        return;
    if (!json.isArray()) {
        if (usable(json))
            spec.points = json.toDouble();
        else
            //: %1 the largest number of points ("1000000")
            ignore("grading.points",
                   ExerciseMessages::tr("not a number of points from 0 to %1, nor a list "
                                        "of one per case")
                       .arg(kMaxPoints, 0, 'f', 0));
        return;
    }
    const QJsonArray list = json.toArray();
    std::vector<double> each;
    for (const QJsonValue &v : list)
        if (usable(v))
            each.push_back(v.toDouble());
    if (each.size() != std::size_t(list.size()))
        ignore("grading.points",
               ExerciseMessages::tr("each case's points must be a number from 0 to %1")
                   .arg(kMaxPoints, 0, 'f', 0));
    else if (list.size() != spec.cases)
        //: %1 how many points the list gives, %2 how many cases the exercise has
        ignore("grading.points", ExerciseMessages::tr("%1 values for %2 cases (one per case)")
                                     .arg(list.size())
                                     .arg(spec.cases));
    else
        spec.casePoints = each;
}

} // namespace

ExerciseRead readExerciseSection(const QJsonValue &json, QStringList *ignored);

QStringList varyNames()
{
    QStringList names;
    for (const char *n : kVaryNames)
        names << QLatin1String(n);
    return names;
}

std::vector<double> pointsPerCase(const GradingSpec &spec)
{
    if (spec.casePoints.size() == std::size_t(spec.cases))
        return spec.casePoints;
    return std::vector<double>(std::size_t(std::max(spec.cases, 0)),
                               spec.cases > 0 ? spec.points / spec.cases : 0.0);
}

QJsonObject exerciseJson(const Exercise &exercise)
{
    if (!exercise.unread.isUndefined())
        return exercise.unread.toObject();
    QJsonObject reference;
    if (exercise.reference.builtIn())
        reference["builtIn"] = QJsonObject{{"shading", toName(exercise.reference.shading)},
                                           {"specular", toName(exercise.reference.specular)}};
    else
        reference = QJsonObject{{"vertex", exercise.reference.vertex},
                                {"fragment", exercise.reference.fragment}};
    const GradingSpec &g = exercise.grading;
    QJsonArray vary;
    for (int i = 0; i < int(kVaryNames.size()); ++i)
        if (g.vary & (1u << i))
            vary.append(QLatin1String(kVaryNames[std::size_t(i)]));
    QJsonArray casePoints;
    for (double p : g.casePoints)
        casePoints.append(p);
    QJsonObject json{
        {"title", exercise.title.isEmpty() ? QJsonValue("") : localizedTextJson(exercise.title)},
        {"task", exercise.task.isEmpty() ? QJsonValue("") : localizedTextJson(exercise.task)},
        {"reference", reference},
        {"grading", QJsonObject{{"cases", g.cases},
                                {"size", QJsonArray{g.size.width(), g.size.height()}},
                                {"tolerance", g.tolerance},
                                {"passShare", g.passShare},
                                {"vary", vary},
                                {"points", g.casePoints.empty() ? QJsonValue(g.points)
                                                                : QJsonValue(casePoints)},
                                {"frameBudget", g.frameBudget}}}};
    if (!exercise.mistakes.empty())
        json["mistakes"] = exerciseMistakesJson(exercise.mistakes);
    return json;
}

ExerciseRead readExercise(const QJsonValue &json, QStringList *ignored)
{
    const qsizetype before = ignored ? ignored->size() : 0;
    ExerciseRead read = readExerciseSection(json, ignored);
    if (!read.error.isEmpty()) {
        // Kept as it is: its fields are not read, so none is named; the error says why.
        if (ignored)
            ignored->erase(ignored->begin() + before, ignored->end());
        read.exercise = Exercise{};
        read.exercise->unread = json;
    }
    return read;
}

ExerciseRead readExerciseSection(const QJsonValue &json, QStringList *ignored)
{
    ExerciseRead read;
    const auto ignore = [&](const QString &path, const QString &why) {
        if (ignored)
            //: a field of an exercise as the file spells it (%1, "exercise.grading.cases") and
            //: why it was not used (%2)
            ignored->append(ExerciseMessages::tr("%1 (%2)").arg(
                escapedName(elidedForMessage("exercise." + path)), why));
    };
    // The sections' names in the errors are the file's words: arguments, never translated.
    if (!json.isObject()) {
        read.error = ExerciseMessages::tr("%1: not an object").arg("exercise");
        return read;
    }
    const QJsonObject o = json.toObject();
    Exercise e;
    // A title or a task that is not text is left out and named, as a lesson's caption is.
    e.title = readLocalizedText(o.value("title"), "title", kMaxExerciseTextCharacters, ignore);
    e.task = readLocalizedText(o.value("task"), "task", kMaxExerciseTextCharacters, ignore);
    const QJsonObject known = exerciseJson(e);
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!known.contains(it.key()) && it.key() != QLatin1String("mistakes"))
            ignore(it.key(), ExerciseMessages::tr("unknown field"));

    const QJsonObject ref = o.value("reference").toObject();
    if (ref.contains("vertex") || ref.contains("fragment")) {
        e.reference.vertex = text(ref, "vertex");
        e.reference.fragment = text(ref, "fragment");
        if (e.reference.vertex.trimmed().isEmpty() || e.reference.fragment.trimmed().isEmpty()) {
            read.error = ExerciseMessages::tr("%1: needs both a vertex and a fragment shader")
                             .arg("exercise.reference");
            return read;
        }
    } else if (ref.contains("builtIn")) {
        const QJsonObject b = ref.value("builtIn").toObject();
        if (const auto s = parseShading(text(b, "shading")))
            e.reference.shading = *s;
        else if (b.contains("shading"))
            //: %1 the words a file may give, as it spells them ("phong, gouraud, flat")
            ignore("reference.builtIn.shading",
                   ExerciseMessages::tr("not %1").arg(shadingNames().join(", ")));
        if (const auto s = parseSpecularModel(text(b, "specular")))
            e.reference.specular = *s;
        else if (b.contains("specular"))
            ignore("reference.builtIn.specular",
                   ExerciseMessages::tr("not %1").arg(specularModelNames().join(", ")));
    } else {
        read.error =
            ExerciseMessages::tr("%1: no reference program (\"reference\": {\"vertex\": ..., "
                                 "\"fragment\": ...} or {\"builtIn\": {...}})")
                .arg("exercise");
        return read;
    }

    e.mistakes = readExerciseMistakes(o.value("mistakes"), e.reference.builtIn(), ignore);

    const QJsonObject g = o.value("grading").toObject();
    const QJsonObject knownGrading = exerciseJson(e).value("grading").toObject();
    for (auto it = g.begin(); it != g.end(); ++it)
        if (!knownGrading.contains(it.key()))
            ignore("grading." + it.key(), ExerciseMessages::tr("unknown field"));
    GradingSpec &spec = e.grading;
    const auto number = [&](const char *key, double lo, double hi, auto &value) {
        const QJsonValue v = g.value(QLatin1String(key));
        if (v.isUndefined())
            return;
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            ignore(QString("grading.%1").arg(key), ExerciseMessages::tr("not a number"));
            return;
        }
        const double d = v.toDouble();
        if (d < lo || d > hi)
            ignore(QString("grading.%1").arg(key), ExerciseMessages::tr("out of range, clamped"));
        value = std::remove_reference_t<decltype(value)>(std::clamp(d, lo, hi));
    };
    number("cases", 1, kMaxCases, spec.cases);
    number("tolerance", 0, 255, spec.tolerance);
    number("passShare", 0.0, 1.0, spec.passShare);
    number("frameBudget", kMinFrameBudget, kMaxFrameBudget, spec.frameBudget);
    if (g.contains("size")) {
        const QJsonArray a = g.value("size").toArray();
        if (a.size() == 2 && a[0].isDouble() && a[1].isDouble() &&
            a[0].toDouble() == a[0].toInt() && a[1].toDouble() == a[1].toInt() &&
            a[0].toInt() >= 16 && a[1].toInt() >= 16 && a[0].toInt() <= kMaxSide &&
            a[1].toInt() <= kMaxSide)
            spec.size = QSize(std::clamp(a[0].toInt(), 16, kMaxSide),
                              std::clamp(a[1].toInt(), 16, kMaxSide));
        else
            ignore("grading.size",
                   ExerciseMessages::tr("not [width, height] in whole pixels, 16 to %1")
                       .arg(kMaxSide));
    }
    if (g.contains("vary") && (!g.value("vary").isArray() || g.value("vary").toArray().isEmpty())) {
        ignore("grading.vary", ExerciseMessages::tr("not a list of parameters; all of them vary"));
    } else if (g.contains("vary")) {
        spec.vary = 0;
        for (const QJsonValue &v : g.value("vary").toArray()) {
            const int i = varyNames().indexOf(v.toString());
            if (i < 0)
                ignore("grading.vary", ExerciseMessages::tr("no such parameter '%1'; those are %2")
                                           .arg(v.toString().left(40), varyNames().join(", ")));
            else
                spec.vary |= 1u << i;
        }
    }
    readPoints(g.value("points"), spec, ignore);
    read.exercise = e;
    return read;
}

std::vector<Scene> gradingCases(const Scene &base, const GradingSpec &spec, std::uint32_t seed)
{
    std::vector<Scene> cases;
    const auto varies = [&](Vary v) { return (spec.vary & unsigned(v)) != 0; };
    for (int k = 0; k < spec.cases; ++k) {
        Scene s = base;
        if (k > 0) {
            // Each case from its own stream: a case does not depend on how many come before.
            Draw draw(seed * 2654435761u + std::uint32_t(k) * 40503u + 1u);
            Light &light = s.lights[0];
            light.enabled = true;
            if (varies(Vary::Light)) {
                const glm::vec3 p = draw.direction() * draw.uniform(2.0f, 4.0f);
                light.position = glm::vec4(p, light.position.w);
            }
            if (varies(Vary::LightW))
                light.position.w = draw.index(2) ? 1.0f : 0.0f;
            if (varies(Vary::LightFrame))
                light.frame = LightFrame(draw.index(3));
            if (varies(Vary::LightColour)) {
                light.colors.ia = draw.colour(0.0f, 0.4f);
                light.colors.id = draw.colour(0.3f, 1.0f);
                light.colors.is = draw.colour(0.3f, 1.0f);
            }
            for (ObjectSettings &o : s.objects) {
                if (varies(Vary::Material)) {
                    o.material.ka = draw.colour(0.0f, 1.0f);
                    o.material.kd = draw.colour(0.0f, 1.0f);
                    o.material.ks = draw.colour(0.0f, 1.0f);
                    o.material.shininess = std::exp(draw.uniform(std::log(2.0f), std::log(200.0f)));
                }
                if (varies(Vary::Scale)) {
                    o.scale = o.scale * draw.colour(0.5f, 1.6f);
                    o.rotationDegrees = draw.colour(-180.0f, 180.0f);
                }
            }
            if (varies(Vary::Camera)) {
                s.camera.yawDegrees = draw.uniform(-180.0f, 180.0f);
                s.camera.pitchDegrees = draw.uniform(-60.0f, 60.0f);
            }
            if (varies(Vary::Projection))
                s.shading.projection = Projection(draw.index(2));
        }
        // A case is one still frame of the programs alone: no turning, no marker, no normal
        // lines and no compare view, whatever the scene was saved with.
        for (ObjectSettings &o : s.objects) {
            o.autoRotate = false;
            o.showNormals = false;
        }
        s.showLight = false;
        s.compare.mode = CompareMode::Off;
        cases.push_back(s);
    }
    return cases;
}

Scene referenceCase(const Scene &caseScene, const ExerciseReference &reference)
{
    Scene s = caseScene;
    if (reference.builtIn()) {
        s.shading.shading = reference.shading;
        s.shading.specular = reference.specular;
    }
    return s;
}

} // namespace lb
