#include "lesson.h"

#include "bounded_read.h"
#include "message_text.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QRegularExpression>

namespace lb {

namespace {

// The translation context of this file's messages.
struct LessonMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Lesson)
};

const char *kLessonFormat = "lightbench-lesson";

// One entry of `ignored`: where, as the file spells it ("step 2: caption.de"; data, never
// translated but for "step"), and why it was not used.
void note(QStringList &ignored, const QString &where, const QString &why)
{
    //: a field of a lesson file (%1, "step 2: caption.de") and why it was not used (%2)
    ignored << LessonMessages::tr("%1 (%2)").arg(escapedName(elidedForMessage(where)), why);
}

// "a title", "a caption", in one language or several (localized_text.h).
LocalizedText readText(const QJsonValue &value, const QString &where, QStringList &ignored)
{
    return readLocalizedText(
        value, where, kMaxLessonTextCharacters,
        [&](const QString &at, const QString &why) { note(ignored, at, why); });
}

// One of `allowed`, or empty with a word in `ignored`.
QString readChoice(const QJsonValue &value, const QStringList &allowed, const QString &where,
                   QStringList &ignored)
{
    if (value.isUndefined() || value.isNull())
        return {};
    if (value.isString() && allowed.contains(value.toString()))
        return value.toString();
    //: %1 a word the file gave, %2 the words allowed (as files spell them)
    note(ignored, where,
         value.isString() ? LessonMessages::tr("\"%1\" is not one of %2")
                                .arg(echoedValue(value.toString(), 60), allowed.join(", "))
                          : LessonMessages::tr("a value that is not text is not one of %1")
                                .arg(allowed.join(", ")));
    return {};
}

struct StepContext
{
    const QDir &dir;
    qint64 &budget;
    LessonRead &read;
};

void readStepScene(const QJsonValue &scene, LessonStep &step, const QString &where,
                   StepContext &context)
{
    SceneFileRead sceneRead;
    if (scene.isObject()) {
        // Held by a lesson of a known version: a scene written by hand inline need not say
        // its own format and version.
        QJsonObject object = scene.toObject();
        if (!object.contains("version"))
            object["version"] = kSceneFileVersion;
        sceneRead = parseSceneObject(object, context.dir);
    } else if (scene.isString() && !scene.toString().isEmpty()) {
        const QString path = QDir::cleanPath(context.dir.absoluteFilePath(scene.toString()));
        step.scenePath = path;
        // Within what is left of the lesson's limit: the same file named 500 times does not
        // take 500 times the memory a lesson may.
        const qint64 size = QFileInfo(path).size();
        if (size > context.budget) {
            //: %1 the step ("step 3"), %2 a path, %3 its size, %4 the limit
            step.error =
                LessonMessages::tr("%1: the scene file %2 (%3) is past what is left of the "
                                   "lesson's limit (%4 for the lesson and its scene files)")
                    .arg(where, echoedValue(scene.toString(), 200), sizeForMessage(size),
                         sizeForMessage(kMaxLessonBytes));
            return;
        }
        sceneRead = readSceneFile(path);
        context.budget -= std::max<qint64>(size, 0);
    } else {
        step.error =
            LessonMessages::tr("%1: no scene (\"scene\" must be a scene object or the name of a "
                               "scene file)")
                .arg(where);
        return;
    }
    if (!sceneRead.file) {
        step.error = QString("%1: %2").arg(where, sceneRead.error);
        return;
    }
    step.scene = *sceneRead.file;
    for (const QString &i : std::as_const(sceneRead.ignored))
        context.read.ignored << QString("%1: scene: %2").arg(where, i);
}

} // namespace

const QStringList &lessonPanels()
{
    static const QStringList panels{"light", "material", "shading", "object",
                                    "scene", "editor",   "probe",   "exercise"};
    return panels;
}

const QStringList &lessonHighlights()
{
    // The lighting model's numbers' controls (lighting_parameters.h), then the others.
    static const QStringList controls = [] {
        QStringList names;
        for (const LightingParameter &p : lightingParameters())
            if (p.highlight && !names.contains(QLatin1String(p.highlight)))
                names << QString::fromLatin1(p.highlight);
        return names + QStringList{"light.w",          "light.frame",        "shading.shading",
                                   "shading.specular", "shading.projection", "shading.terms",
                                   "compare",          "object.transform",   "editor"};
    }();
    return controls;
}

LessonRead parseLesson(const QByteArray &bytes, const QDir &dir, const QString &name, qint64 budget)
{
    LessonRead read;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        //: %1 a path, %2 Qt's JSON parser's reason
        read.error = LessonMessages::tr("%1: not a lesson file: %2 at byte %3")
                         .arg(name, parseError.errorString(), QString::number(parseError.offset));
        return read;
    }
    const QJsonObject root = document.object();
    if (!document.isObject() || root["format"] != QJsonValue(kLessonFormat)) {
        // A scene file is the likeliest mistake: say so rather than "no steps".
        read.error = root["format"] == QJsonValue("lightbench-scene")
                         ? LessonMessages::tr(
                               "%1: a scene file, not a lesson (open it with File > Open Scene)")
                               .arg(name)
                         : LessonMessages::tr("%1: not a lesson file (\"format\" is not \"%2\")")
                               .arg(name, kLessonFormat);
        return read;
    }
    const QJsonValue version = root["version"];
    if (!version.isDouble() || version.toDouble() < 1)
        note(read.ignored, "version",
             LessonMessages::tr("missing or not a number; read as %1").arg(kLessonFileVersion));
    else if (version.toDouble() > kLessonFileVersion)
        note(
            read.ignored, QString("version %1").arg(version.toDouble()),
            LessonMessages::tr("newer than this lightbench's %1: what it does not know is left out")
                .arg(kLessonFileVersion));
    const QJsonValue steps = root["steps"];
    if (!steps.isArray() || steps.toArray().isEmpty()) {
        read.error =
            LessonMessages::tr("%1: the lesson has no steps (\"steps\" must be a list of steps)")
                .arg(name);
        return read;
    }
    if (steps.toArray().size() > kMaxLessonSteps) {
        read.error = LessonMessages::tr("%1: %2 steps; a lesson may have at most %3")
                         .arg(name, QString::number(steps.toArray().size()),
                              QString::number(kMaxLessonSteps));
        return read;
    }
    Lesson lesson;
    lesson.title = readText(root["title"], "title", read.ignored);
    StepContext context{dir, budget, read};
    const QJsonArray list = steps.toArray();
    for (int i = 0; i < int(list.size()); ++i) {
        //: where in a lesson file a message is about: "step 3: title (not text)"
        const QString where = LessonMessages::tr("step %1").arg(i + 1);
        LessonStep step;
        if (!list[i].isObject()) {
            step.error = LessonMessages::tr("%1: not an object").arg(where);
        } else {
            const QJsonObject s = list[i].toObject();
            step.title = readText(s["title"], where + ": title", read.ignored);
            step.caption = readText(s["caption"], where + ": caption", read.ignored);
            step.panel = readChoice(s["panel"], lessonPanels(), where + ": panel", read.ignored);
            step.highlight =
                readChoice(s["highlight"], lessonHighlights(), where + ": highlight", read.ignored);
            readStepScene(s["scene"], step, where, context);
        }
        if (!step.error.isEmpty())
            read.stepErrors << step.error;
        lesson.steps.push_back(std::move(step));
    }
    read.lesson = std::move(lesson);
    return read;
}

LessonRead readLessonFile(const QString &path)
{
    const BoundedRead bytes =
        readBounded(path, {QT_TRANSLATE_NOOP("lb::FileLimit", "a lesson file"), kMaxLessonBytes});
    if (!bytes.error.isEmpty()) {
        LessonRead read;
        read.error = bytes.error;
        return read;
    }
    return parseLesson(bytes.bytes, QFileInfo(path).absoluteDir(), echoedPath(path),
                       kMaxLessonBytes - bytes.bytes.size());
}

QByteArray lessonFileBytes(const Lesson &lesson, const QDir &dir)
{
    QJsonObject root{{"format", kLessonFormat}, {"version", kLessonFileVersion}};
    if (!lesson.title.isEmpty())
        root["title"] = localizedTextJson(lesson.title);
    QJsonArray steps;
    for (const LessonStep &step : lesson.steps) {
        QJsonObject s;
        if (!step.title.isEmpty())
            s["title"] = localizedTextJson(step.title);
        if (!step.caption.isEmpty())
            s["caption"] = localizedTextJson(step.caption);
        if (!step.panel.isEmpty())
            s["panel"] = step.panel;
        if (!step.highlight.isEmpty())
            s["highlight"] = step.highlight;
        if (step.scenePath.isEmpty())
            s["scene"] = sceneFileJson(step.scene, dir);
        else // a built-in example (":/examples/...") stays as it is
            s["scene"] = step.scenePath.startsWith(":/") ? step.scenePath
                                                         : dir.relativeFilePath(step.scenePath);
        steps.append(s);
    }
    root["steps"] = steps;
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString writeLessonFile(const QString &path, const Lesson &lesson)
{
    // Never a file that readLessonFile() would refuse: one limit for both.
    return writeWithinLimit(path, lessonFileBytes(lesson, QFileInfo(path).absoluteDir()),
                            QT_TRANSLATE_NOOP("lb::FileLimit", "the lesson"),
                            {QT_TRANSLATE_NOOP("lb::FileLimit", "a lesson file"), kMaxLessonBytes});
}

} // namespace lb
