#include "exercise_mistakes.h"

#include "dialect.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>

namespace lb {

namespace {

// The exercise's own translation context: a translator finds these beside its other fields'.
struct ExerciseMistakesMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Exercise)
};

constexpr int kMaxHintCharacters = 8000; // as an exercise's task, in one language

using Ignore = std::function<void(const QString &, const QString &)>;

// A built-in switch that is a word of `names`: set, or left unset and named.
template <typename T>
void readWord(const QJsonObject &o, const char *key, const QString &where,
              std::optional<T> (*parse)(const QString &), const QStringList &names,
              std::optional<T> &value, const Ignore &ignore)
{
    if (!o.contains(QLatin1String(key)))
        return;
    if (const auto v = parse(o.value(QLatin1String(key)).toString()))
        value = *v;
    else
        //: %1 the words a file may give, as it spells them ("phong, gouraud, flat")
        ignore(where + "." + key, ExerciseMistakesMessages::tr("not %1").arg(names.join(", ")));
}

void readSwitch(const QJsonObject &o, const char *key, const QString &where,
                std::optional<bool> &value, const Ignore &ignore)
{
    if (!o.contains(QLatin1String(key)))
        return;
    if (o.value(QLatin1String(key)).isBool())
        value = o.value(QLatin1String(key)).toBool();
    else
        ignore(where + "." + key, ExerciseMistakesMessages::tr("not true or false"));
}

BuiltInMistake readBuiltIn(const QJsonObject &b, const QString &where, const Ignore &ignore)
{
    BuiltInMistake m;
    const QStringList known{"shading", "specular", "terms", "normalsByModelView", "lightFrame"};
    for (auto it = b.begin(); it != b.end(); ++it)
        if (!known.contains(it.key()))
            ignore(where + "." + it.key(), ExerciseMistakesMessages::tr("unknown field"));
    readWord(b, "shading", where, &parseShading, shadingNames(), m.shading, ignore);
    readWord(b, "specular", where, &parseSpecularModel, specularModelNames(), m.specular, ignore);
    readWord(b, "lightFrame", where, &parseLightFrame, lightFrameNames(), m.lightFrame, ignore);
    readSwitch(b, "normalsByModelView", where, m.normalsByModelView, ignore);
    if (b.contains("terms")) {
        if (!b.value("terms").isObject())
            ignore(where + ".terms", ExerciseMistakesMessages::tr("not an object"));
        const QJsonObject t = b.value("terms").toObject();
        for (auto it = t.begin(); it != t.end(); ++it)
            if (!QStringList{"ambient", "diffuse", "specular"}.contains(it.key()))
                ignore(where + ".terms." + it.key(), ExerciseMistakesMessages::tr("unknown field"));
        readSwitch(t, "ambient", where + ".terms", m.ambient, ignore);
        readSwitch(t, "diffuse", where + ".terms", m.diffuse, ignore);
        readSwitch(t, "specular", where + ".terms", m.specularTerm, ignore);
    }
    return m;
}

// One entry, or none (told to `ignore`) when it cannot be used.
std::optional<ExerciseMistake> readMistake(const QJsonValue &json, const QString &where,
                                           bool referenceBuiltIn, const Ignore &ignore)
{
    if (!json.isObject()) {
        ignore(where, ExerciseMistakesMessages::tr("not an object"));
        return std::nullopt;
    }
    const QJsonObject o = json.toObject();
    const QStringList known{"name", "hint", "vertex", "fragment", "builtIn"};
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!known.contains(it.key()))
            ignore(where + "." + it.key(), ExerciseMistakesMessages::tr("unknown field"));
    ExerciseMistake m;
    const QJsonValue name = o.value("name");
    if (!name.isString() || name.toString().trimmed().isEmpty() ||
        name.toString().size() > kMaxMistakeNameCharacters) {
        ignore(where + ".name", ExerciseMistakesMessages::tr(
                                    "not a name of 1 to %1 characters; the mistake is left out")
                                    .arg(kMaxMistakeNameCharacters));
        return std::nullopt;
    }
    m.name = name.toString();
    m.hint = readLocalizedText(o.value("hint"), where + ".hint", kMaxHintCharacters, ignore);
    if (m.hint.isEmpty()) {
        // A mistake without words would be found and then not said: no use to a student.
        ignore(where + ".hint",
               ExerciseMistakesMessages::tr("no usable hint; the mistake is left out"));
        return std::nullopt;
    }
    for (const char *stage : {"vertex", "fragment"}) {
        if (!o.contains(QLatin1String(stage)))
            continue;
        const QJsonValue v = o.value(QLatin1String(stage));
        // Drawn in place of the reference's stage, a stage that cannot be read would grade
        // the student against some other program: the whole mistake goes.
        if (!v.isString() || v.toString().trimmed().isEmpty() ||
            v.toString().size() > kMaxSourceCharacters) {
            ignore(where + "." + stage,
                   ExerciseMistakesMessages::tr(
                       "not a shader's text of up to 1 MiB; the mistake is left out"));
            return std::nullopt;
        }
        (QLatin1String(stage) == QLatin1String("vertex") ? m.vertex : m.fragment) = v.toString();
    }
    const bool program = !m.isBuiltIn();
    if (program && o.contains("builtIn")) {
        ignore(where, ExerciseMistakesMessages::tr(
                          "both a program and a built-in; the mistake is left out"));
        return std::nullopt;
    }
    if (program && referenceBuiltIn && (m.vertex.isEmpty() || m.fragment.isEmpty())) {
        ignore(where, ExerciseMistakesMessages::tr(
                          "needs both a vertex and a fragment shader: the reference is the "
                          "built-in program; the mistake is left out"));
        return std::nullopt;
    }
    if (!program) {
        if (!o.value("builtIn").isObject()) {
            ignore(where,
                   ExerciseMistakesMessages::tr("neither a program (\"vertex\", \"fragment\") nor "
                                                "\"builtIn\": {...}; the mistake is left out"));
            return std::nullopt;
        }
        // The built-in program with a switch changed is "the reference with one mistake" only
        // when the reference is the built-in program: beside a teacher's program, with its own
        // uniforms and constants, it would draw something unrelated and match nothing fairly.
        if (!referenceBuiltIn) {
            ignore(where, ExerciseMistakesMessages::tr(
                              "a built-in mistake needs a built-in reference; give the "
                              "mistake as a program; the mistake is left out"));
            return std::nullopt;
        }
        m.builtIn = readBuiltIn(o.value("builtIn").toObject(), where + ".builtIn", ignore);
    }
    return m;
}

} // namespace

std::vector<ExerciseMistake> readExerciseMistakes(const QJsonValue &json, bool referenceBuiltIn,
                                                  const Ignore &ignore)
{
    std::vector<ExerciseMistake> mistakes;
    if (json.isUndefined())
        return mistakes;
    if (!json.isArray()) {
        ignore("mistakes", ExerciseMistakesMessages::tr("not a list"));
        return mistakes;
    }
    const QJsonArray list = json.toArray();
    for (int i = 0; i < list.size(); ++i) {
        const QString where = QString("mistakes[%1]").arg(i);
        if (i >= kMaxExerciseMistakes) {
            // Each mistake costs a program build and a frame per failing case: bounded.
            ignore(where,
                   ExerciseMistakesMessages::tr("more than %1 mistakes; the rest are left out")
                       .arg(kMaxExerciseMistakes));
            break;
        }
        if (auto m = readMistake(list[i], where, referenceBuiltIn, ignore))
            mistakes.push_back(std::move(*m));
    }
    return mistakes;
}

QJsonValue exerciseMistakesJson(const std::vector<ExerciseMistake> &mistakes)
{
    QJsonArray list;
    for (const ExerciseMistake &m : mistakes) {
        QJsonObject o{{"name", m.name}, {"hint", localizedTextJson(m.hint)}};
        if (!m.isBuiltIn()) {
            if (!m.vertex.isEmpty())
                o["vertex"] = m.vertex;
            if (!m.fragment.isEmpty())
                o["fragment"] = m.fragment;
        } else {
            const BuiltInMistake &b = m.builtIn;
            QJsonObject built, terms;
            if (b.shading)
                built["shading"] = toName(*b.shading);
            if (b.specular)
                built["specular"] = toName(*b.specular);
            if (b.lightFrame)
                built["lightFrame"] = toName(*b.lightFrame);
            if (b.normalsByModelView)
                built["normalsByModelView"] = *b.normalsByModelView;
            if (b.ambient)
                terms["ambient"] = *b.ambient;
            if (b.diffuse)
                terms["diffuse"] = *b.diffuse;
            if (b.specularTerm)
                terms["specular"] = *b.specularTerm;
            if (!terms.isEmpty())
                built["terms"] = terms;
            o["builtIn"] = built;
        }
        list.append(o);
    }
    return list;
}

Scene mistakeScene(const Scene &caseScene, const ExerciseMistake &mistake)
{
    Scene s = caseScene;
    if (!mistake.isBuiltIn())
        return s;
    const BuiltInMistake &b = mistake.builtIn;
    ShadingSettings &shading = s.shading;
    shading.shading = b.shading.value_or(shading.shading);
    shading.specular = b.specular.value_or(shading.specular);
    shading.terms.ambient = b.ambient.value_or(shading.terms.ambient);
    shading.terms.diffuse = b.diffuse.value_or(shading.terms.diffuse);
    shading.terms.specular = b.specularTerm.value_or(shading.terms.specular);
    shading.normalsByModelView = b.normalsByModelView.value_or(shading.normalsByModelView);
    if (b.lightFrame)
        // The light's numbers as given, read in the wrong frame: "left in world coordinates".
        for (Light &light : s.lights)
            light.frame = *b.lightFrame;
    return s;
}

} // namespace lb
