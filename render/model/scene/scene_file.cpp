#include "scene_file.h"

#include "bounded_read.h"
#include "dialect.h"
#include "message_text.h"
#include "scene_json_reader.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace lb {

namespace {

// The translation context of this file's messages.
struct SceneFileMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::SceneFile)
};

const char *kSceneFormat = "lightbench-scene";
// How files written before the "edited" field marked an edited program: an English suffix on
// its name, never translated.
const QLatin1String kLegacyEditedSuffix(" (edited)");

// A "program" object whose sources are known to be good.
ProgramText programText(const QJsonObject &p, QStringList &ignored)
{
    SceneJsonReader reader(&ignored);
    ProgramText text{{}, p["vertex"].toString(), p["fragment"].toString()};
    reader.name(p, "name", "program", text.name);
    const QJsonValue edited = p["edited"];
    if (edited.isBool()) {
        text.edited = edited.toBool();
    } else if (!edited.isUndefined()) {
        reader.ignore("program.edited", SceneFileMessages::tr("not true or false; read as false"));
    } else if (text.name.value("en").endsWith(kLegacyEditedSuffix)) {
        text.name["en"].chop(kLegacyEditedSuffix.size());
        text.edited = true;
    }
    return text;
}

} // namespace

QByteArray sceneFileBytes(const SceneFile &file, const QDir &dir)
{
    return QJsonDocument(sceneFileJson(file, dir)).toJson(QJsonDocument::Indented);
}

QJsonObject sceneFileJson(const SceneFile &file, const QDir &dir)
{
    QJsonObject root = file.scene.toJson();
    // Mesh and image files are stored relative to the scene file, so that a folder moves as a
    // whole.
    QJsonArray objects = root["objects"].toArray();
    for (int i = 0; i < int(objects.size()); ++i) {
        const ObjectSettings &o = file.scene.objects[std::size_t(i)];
        QJsonObject object = objects[i].toObject();
        // An example's image (":/examples/bricks.png") is built in: it stays as it is.
        const auto relative = [&](const QString &path) {
            return path.startsWith(":/") ? path : dir.relativeFilePath(path);
        };
        if (!o.meshPath.isEmpty())
            object["mesh"] = relative(o.meshPath);
        if (!o.textureFile.isEmpty())
            object["textureFile"] = relative(o.textureFile);
        objects[i] = object;
    }
    root["objects"] = objects;
    root["format"] = kSceneFormat;
    root["version"] = kSceneFileVersion;
    if (file.exercise)
        root["exercise"] = file.exercise->unread.isUndefined()
                               ? QJsonValue(exerciseJson(*file.exercise))
                               : file.exercise->unread;
    if (file.program)
        root["program"] = QJsonObject{{"name", SceneJsonReader::nameJson(file.program->name)},
                                      {"edited", file.program->edited},
                                      {"vertex", file.program->vertex},
                                      {"fragment", file.program->fragment}};
    return root;
}

SceneFileRead parseSceneFile(const QByteArray &bytes, const QDir &dir, const QString &name)
{
    SceneFileRead read;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        //: %1 a path, %2 Qt's JSON parser's reason
        read.error = SceneFileMessages::tr("%1: not a scene file: %2 at byte %3")
                         .arg(name, parseError.errorString(), QString::number(parseError.offset));
        return read;
    }
    if (!document.isObject()) {
        read.error =
            SceneFileMessages::tr("%1: not a scene file: the JSON is not an object").arg(name);
        return read;
    }
    // A lesson where a scene is asked for (a step naming a lesson): read as a scene it drew
    // the default scene with two lines of ignored fields and exit 0.
    if (document.object()["format"] == QJsonValue("lightbench-lesson")) {
        read.error =
            SceneFileMessages::tr("%1: a lesson file, not a scene file (open it as a lesson)")
                .arg(name);
        return read;
    }
    return parseSceneObject(document.object(), dir);
}

SceneFileRead parseSceneObject(QJsonObject root, const QDir &dir)
{
    SceneFileRead read; // an object has no error of its own, only what is ignored
    SceneJsonReader fields(&read.ignored);

    // A file from a newer lightbench is read for what this one knows.
    const QJsonValue format = root.take("format");
    if (!format.isUndefined() && format != QJsonValue(kSceneFormat))
        fields.ignore("format", SceneFileMessages::tr("expected \"%1\"").arg(kSceneFormat));
    const QJsonValue version = root.take("version");
    if (!version.isDouble() || version.toDouble() < 1)
        fields.ignore(
            "version",
            SceneFileMessages::tr("missing or not a number; read as %1").arg(kSceneFileVersion));
    else if (version.toDouble() > kSceneFileVersion)
        fields.ignore(QString("version %1").arg(version.toDouble()),
                      SceneFileMessages::tr(
                          "newer than this lightbench's %1: what it does not know is left out")
                          .arg(kSceneFileVersion));

    SceneFile file;
    const QJsonValue program = root.take("program");
    if (program.isObject()) {
        const QJsonObject p = program.toObject();
        const QJsonValue vertex = p["vertex"], fragment = p["fragment"];
        // Too long is said as too long (it was "needs ... sources as strings", which they were).
        const auto tooLong = [](const QJsonValue &v) {
            return v.toString().size() > kMaxSourceCharacters;
        };
        if (!vertex.isString() || !fragment.isString())
            fields.ignore("program",
                          SceneFileMessages::tr("needs vertex and fragment sources as strings"));
        else if (tooLong(vertex))
            //: %1 the shader's characters; %2 the most a shader may have
            fields.ignore("program", SceneFileMessages::tr("the vertex shader has %1 characters, "
                                                           "more than a shader may have (%2)")
                                         .arg(QString::number(vertex.toString().size()),
                                              QString::number(kMaxSourceCharacters)));
        else if (tooLong(fragment))
            //: %1 the shader's characters; %2 the most a shader may have
            fields.ignore("program", SceneFileMessages::tr("the fragment shader has %1 characters, "
                                                           "more than a shader may have (%2)")
                                         .arg(QString::number(fragment.toString().size()),
                                              QString::number(kMaxSourceCharacters)));
        else
            file.program = programText(p, read.ignored);
    } else if (!program.isUndefined() && !program.isNull()) {
        fields.ignore("program", SceneFileMessages::tr("not an object"));
    }

    const QJsonValue exercise = root.take("exercise");
    if (!exercise.isUndefined()) {
        ExerciseRead e = readExercise(exercise, &read.ignored);
        file.exercise = e.exercise;
        read.exerciseError = e.error;
        if (!e.error.isEmpty())
            //: %1 why an exercise section cannot be graded against
            read.ignored << SceneFileMessages::tr("%1 (the section is kept as it is)").arg(e.error);
    }
    file.scene = Scene::fromJson(root, &read.ignored);
    for (ObjectSettings &object : file.scene.objects)
        for (QString *path : {&object.meshPath, &object.textureFile})
            if (!path->isEmpty())
                *path = QDir::cleanPath(dir.absoluteFilePath(*path));
    read.file = file;
    return read;
}

SceneFileRead readSceneFile(const QString &path)
{
    const BoundedRead bytes =
        readBounded(path, {QT_TRANSLATE_NOOP("lb::FileLimit", "a scene file"), kMaxSceneFileBytes});
    if (!bytes.error.isEmpty()) {
        SceneFileRead read;
        read.error = bytes.error;
        return read;
    }
    return parseSceneFile(bytes.bytes, QFileInfo(path).absoluteDir(), echoedPath(path));
}

QString writeSceneFile(const QString &path, const SceneFile &file)
{
    // Never a file that readSceneFile() would refuse: one limit for both.
    return writeWithinLimit(
        path, sceneFileBytes(file, QFileInfo(path).absoluteDir()),
        QT_TRANSLATE_NOOP("lb::FileLimit", "the scene"),
        {QT_TRANSLATE_NOOP("lb::FileLimit", "a scene file"), kMaxSceneFileBytes});
}

} // namespace lb
