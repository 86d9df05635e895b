// Scene files: what is saved opens as the same scene; mangled files never crash and never
// give values outside the model's limits.
#include "dialect.h"
#include "lesson.h"
#include "localized_text.h"
#include "safe_write.h"
#include "scene_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

#include <sys/stat.h>

using namespace lb;

namespace {

SceneFile sampleFile(const QDir &dir)
{
    SceneFile f;
    f.scene.lights[1].enabled = true;
    f.scene.lights[1].frame = LightFrame::Object;
    f.scene.objects[0].material.shininess = 42;
    f.scene.shading.shading = Shading::Gouraud;
    f.scene.objects[0].meshPath = dir.filePath("meshes/bunny.ply");
    f.scene.objects[0].textureFile = dir.filePath("images/fur.jpg");
    f.scene.objects[0].sampling = {TextureWrap::Clamp, TextureFilter::Nearest, true};
    f.scene.objects[0].normals = NormalMode::Flat;
    f.scene.objects[0].cullBackFaces = true;
    f.scene.camera.orbit(30, -10);
    f.scene.compare.mode = CompareMode::SideBySide;
    f.scene.shaderValues["bands"] = {4.0f};
    f.program = ProgramText{plainText("toon"), "void main() { gl_Position = vec4(0.0); }",
                            "void main() { gl_FragColor = vec4(1.0); }", true};
    return f;
}

// Every value the model holds is one it could have been given by the panels.
QString outsideLimits(const Scene &s)
{
    for (const Light &l : s.lights) {
        if (l.position.w != 0.0f && l.position.w != 1.0f)
            return "light w";
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(l.position[i]) || std::abs(l.position[i]) > limits::kMaxCoordinate)
                return "light position";
        for (const glm::vec3 &c : {l.colors.ia, l.colors.id, l.colors.is})
            for (int i = 0; i < 3; ++i)
                if (!(c[i] >= 0.0f && c[i] <= 1.0f))
                    return "light colour";
    }
    if (!(s.objects[0].material.shininess >= limits::kMinShininess &&
          s.objects[0].material.shininess <= limits::kMaxShininess))
        return "shininess";
    if (s.objects[0].tessellation < limits::kMinTessellation ||
        s.objects[0].tessellation > limits::kMaxTessellation)
        return "tessellation";
    for (int i = 0; i < 3; ++i)
        if (!(s.objects[0].scale[i] >= limits::kMinScale &&
              s.objects[0].scale[i] <= limits::kMaxScale))
            return "scale";
    if (!(s.compare.wipe >= 0.0f && s.compare.wipe <= 1.0f))
        return "wipe";
    if (!std::isfinite(s.camera.distance) || s.camera.distance <= 0.0f)
        return "camera distance";
    return {};
}

QJsonValue randomValue(QRandomGenerator &rng)
{
    switch (rng.bounded(9)) {
    case 0:
        return QJsonValue();
    case 1:
        return rng.bounded(2) == 1;
    case 2:
        return rng.bounded(2000) - 1000.0;
    case 3:
        return 1e300 * (rng.bounded(2) ? 1 : -1);
    case 4:
        return "phong";
    case 5:
        return QString(rng.bounded(40), QChar(0x41 + rng.bounded(26)));
    case 6:
        return QJsonArray{1, 2, 3, rng.bounded(3)};
    case 7:
        return QJsonArray{"x", QJsonObject{}, 0.5};
    default:
        return QJsonObject{{"position", QJsonArray{0, 0, 0, 0}}, {"enabled", 3}};
    }
}

// Replaces, removes or adds one value somewhere in the tree.
QJsonValue mangle(const QJsonValue &v, QRandomGenerator &rng, int depth)
{
    if (depth > 0 && rng.bounded(4) == 0)
        return randomValue(rng);
    if (v.isObject()) {
        QJsonObject o = v.toObject();
        const QStringList keys = o.keys();
        if (!keys.isEmpty()) {
            const QString key = keys[int(rng.bounded(keys.size()))];
            switch (rng.bounded(5)) {
            case 0:
                o.remove(key);
                break;
            case 1:
                o["unknown" + QString::number(rng.bounded(10))] = randomValue(rng);
                break;
            default:
                o[key] = mangle(o[key], rng, depth + 1);
            }
        }
        return o;
    }
    if (v.isArray()) {
        QJsonArray a = v.toArray();
        if (a.isEmpty() || rng.bounded(5) == 0)
            a.append(randomValue(rng));
        else {
            const int i = int(rng.bounded(a.size()));
            a[i] = mangle(a[i], rng, depth + 1);
        }
        return a;
    }
    return randomValue(rng);
}

} // namespace

class TestSceneFile : public QObject
{
    Q_OBJECT
private slots:
    void savedSceneOpensTheSame()
    {
        QTemporaryDir tmp;
        const QDir dir(tmp.path());
        const SceneFile f = sampleFile(dir);
        const QString path = dir.filePath("lesson.json");
        QCOMPARE(writeSceneFile(path, f), QString());
        const SceneFileRead read = readSceneFile(path);
        QVERIFY2(read.error.isEmpty(), qPrintable(read.error));
        QVERIFY2(read.ignored.isEmpty(), qPrintable(read.ignored.join(", ")));
        QVERIFY(read.file->scene == f.scene);
        QVERIFY(read.file->program == f.program);

        // The mesh and the image are written relative to the file, so a folder handed out keeps
        // working.
        QFile raw(path);
        QVERIFY(raw.open(QIODevice::ReadOnly));
        const QJsonObject json = QJsonDocument::fromJson(raw.readAll()).object();
        QCOMPARE(json["objects"][0]["mesh"].toString(), QString("meshes/bunny.ply"));
        QCOMPARE(json["objects"][0]["textureFile"].toString(), QString("images/fur.jpg"));
        QCOMPARE(json["version"].toInt(), kSceneFileVersion);
        QCOMPARE(json["program"]["fragment"].toString(), f.program->fragment);
        const QDir moved("/elsewhere/class");
        const SceneFileRead there = parseSceneFile(sceneFileBytes(f, dir), moved, "moved.json");
        QCOMPARE(there.file->scene.objects[0].meshPath,
                 QString("/elsewhere/class/meshes/bunny.ply"));
        QCOMPARE(there.file->scene.objects[0].textureFile,
                 QString("/elsewhere/class/images/fur.jpg"));
        // An example's built-in image stays built in.
        SceneFile example = f;
        example.scene.objects[0].textureFile = ":/examples/bricks.png";
        QCOMPARE(parseSceneFile(sceneFileBytes(example, dir), moved, "e.json")
                     .file->scene.objects[0]
                     .textureFile,
                 QString(":/examples/bricks.png"));

        // No program: the built-in one, which follows the shading choice.
        SceneFile builtIn = f;
        builtIn.program.reset();
        QVERIFY(!parseSceneFile(sceneFileBytes(builtIn, dir), dir, "b").file->program);
    }

    void editedIsDataAndOldEditedNamesStillRead()
    {
        const QDir dir = QDir::temp();
        const SceneFile f = sampleFile(dir);
        const QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(f, dir)).object();
        QCOMPARE(json["program"]["name"].toString(), QString("toon")); // no words in the name
        QCOMPARE(json["program"]["edited"].toBool(), true);

        // Before the "edited" field, the name carried an English suffix: read as edited.
        QJsonObject old = json, program = json["program"].toObject();
        program.remove("edited");
        program["name"] = "toon (edited)";
        old["program"] = program;
        SceneFileRead read = parseSceneFile(QJsonDocument(old).toJson(), dir, "old.json");
        QVERIFY(read.ignored.isEmpty());
        QVERIFY(read.file->program == f.program);
        program["name"] = "toon";
        old["program"] = program;
        read = parseSceneFile(QJsonDocument(old).toJson(), dir, "old.json");
        QVERIFY(!read.file->program->edited);

        // With the field, the name is taken as it is, whatever it ends with.
        program["name"] = "my (edited)";
        program["edited"] = false;
        old["program"] = program;
        read = parseSceneFile(QJsonDocument(old).toJson(), dir, "new.json");
        QCOMPARE(read.file->program->name, plainText("my (edited)"));
        QVERIFY(!read.file->program->edited);
        program["edited"] = "yes";
        old["program"] = program;
        read = parseSceneFile(QJsonDocument(old).toJson(), dir, "new.json");
        QVERIFY(!read.file->program->edited);
        QVERIFY(read.ignored.join(' ').contains("program.edited"));
    }

    // An object's and a program's name may be given in several languages, as captions are
    // (the shipped examples do: issue 49, item 17); the shown one follows the lessons'
    // language, saving keeps them all, and what is no language or no text is named, escaped.
    void namesByLanguage()
    {
        const QDir dir = QDir::temp();
        QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(sampleFile(dir), dir)).object();
        QJsonArray objects = json["objects"].toArray();
        QJsonObject object = objects[0].toObject();
        object["name"] = QJsonObject{{"en", "sphere"},
                                     {"pt", "esfera"},
                                     {"de", 5},
                                     {"\u001b[2J", "x"},
                                     {"fr", QString(4097, 'x')}};
        objects[0] = object;
        json["objects"] = objects;
        QJsonObject program = json["program"].toObject();
        program["name"] = QJsonObject{{"en", "exercise"}, {"pt", "exercício"}};
        json["program"] = program;
        const SceneFileRead read = parseSceneFile(QJsonDocument(json).toJson(), dir, "n.json");
        QVERIFY(read.file);
        const QString ignored = read.ignored.join("|");
        QVERIFY2(ignored.contains("objects[0].name.de (not text)") &&
                     ignored.contains("(not a language code)") && !ignored.contains("\u001b") &&
                     ignored.contains("objects[0].name.fr (4097 characters; at most 4096)"),
                 qPrintable(ignored));
        const ObjectSettings &o = read.file->scene.objects[0];
        QCOMPARE(o.name, (LocalizedText{{"en", "sphere"}, {"pt", "esfera"}}));
        setDefaultLessonLanguage("pt");
        QCOMPARE(displayName(o), QString("esfera"));
        setDefaultLessonLanguage("de"); // none given: English
        QCOMPARE(displayName(o), QString("sphere"));
        setDefaultLessonLanguage("en");
        QCOMPARE(read.file->program->name,
                 (LocalizedText{{"en", "exercise"}, {"pt", "exercício"}}));
        // Saved again, as read; a name in English alone is a plain string.
        const SceneFileRead again =
            parseSceneFile(sceneFileBytes(*read.file, dir), dir, "again.json");
        QVERIFY(again.ignored.isEmpty());
        QCOMPARE(again.file->scene.objects[0].name, o.name);
        QCOMPARE(again.file->program->name, read.file->program->name);
        SceneFile plain = *read.file;
        plain.scene.objects[0].name = plainText("moon");
        const QJsonObject written = QJsonDocument::fromJson(sceneFileBytes(plain, dir)).object();
        QCOMPARE(written["objects"][0]["name"].toString(), QString("moon"));
    }

    void filesThatAreNotScenesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message");
        QTest::newRow("empty") << QByteArray() << "not a scene file";
        QTest::newRow("text") << QByteArray("hello") << "not a scene file";
        QTest::newRow("truncated") << QByteArray("{\"lights\": [") << "not a scene file";
        QTest::newRow("array") << QByteArray("[1, 2]") << "the JSON is not an object";
        QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0", 10) << "not a scene file";
    }

    void filesThatAreNotScenesAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        const SceneFileRead read = parseSceneFile(bytes, QDir("/tmp"), "x.json");
        QVERIFY(!read.file);
        QVERIFY2(read.error.startsWith("x.json: ") && read.error.contains(message),
                 qPrintable(read.error));
    }

    // Saves never replace what is not a regular file (a FIFO here; /dev/null as root became a
    // JSON file), and files that belong together are replaced together or not at all.
    void savesRefuseDevicesAndWritePairsTogether()
    {
        QTemporaryDir tmp;
        const QString fifo = tmp.filePath("pipe.json");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const QString error = writeSceneFile(fifo, sampleFile(QDir(tmp.path())));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile()); // still the FIFO

        const QString first = tmp.filePath("pair.vert"), folder = tmp.filePath("pair.frag");
        QVERIFY(writeFileSafely(first, "old").isEmpty());
        QVERIFY(QDir(tmp.path()).mkdir("pair.frag"));
        QVERIFY(!writeFilesSafely({{first, "new"}, {folder, "new"}}).isEmpty());
        QFile f(first);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("old")); // the pair's other half was not replaced
        QCOMPARE(QDir(tmp.path()).entryList(QDir::Files), QStringList{"pair.vert"}); // no leftovers
    }

    // What is saved opens again: one limit for both. A scene at every limit of what the reader
    // keeps (the most uniform values with the longest names, both sources at the longest,
    // written as \u0001 escapes: six bytes a character) fits in a scene file and comes back
    // whole; one beyond (a window can hold more values than a file keeps) is refused by the
    // writer with its size, and the old file stays. A scene of 1.5 million values read from
    // a compact file used to be saved indented, larger than the reader takes.
    void whatIsSavedOpensAgain()
    {
        QTemporaryDir tmp;
        SceneFile f;
        const QString longest(limits::kMaxShaderValueName - 8, QChar('u'));
        for (int i = 0; i < limits::kMaxShaderValues; ++i)
            f.scene.shaderValues[longest + QString::asprintf("%08d", i)] = {-3.4e38f, 1.0f / 3.0f,
                                                                            1e-30f, 7.0f};
        const QString source(kMaxSourceCharacters, QChar(1));
        f.program = ProgramText{plainText("at the limits"), source, source, true};
        const QString path = tmp.filePath("limits.json");
        QCOMPARE(writeSceneFile(path, f), QString());
        QVERIFY2(QFileInfo(path).size() <= kMaxSceneFileBytes,
                 qPrintable(QString::number(QFileInfo(path).size())));
        const SceneFileRead read = readSceneFile(path);
        QVERIFY2(read.file, qPrintable(read.error));
        QVERIFY2(read.ignored.isEmpty(), qPrintable(read.ignored.join("; ")));
        QVERIFY(read.file->scene.shaderValues == f.scene.shaderValues);
        QVERIFY(read.file->program == f.program);

        // Beyond: the reader keeps the first kMaxShaderValues and says so; the writer
        // refuses what the reader could not open.
        SceneFile more = f;
        for (int i = 0; i < 50000; ++i)
            more.scene.shaderValues[QString("extra%1").arg(i) + longest] = {0, 0, 0, 0};
        const QString error = writeSceneFile(path, more);
        QVERIFY2(error.startsWith(path + ": not saved: the scene would take ") &&
                     error.contains("more than a scene file may be (64 MB)"),
                 qPrintable(error));
        QCOMPARE(readSceneFile(path).file->program, f.program); // the old file
        QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(SceneFile{}, QDir())).object();
        QJsonObject values;
        for (int i = 0; i < limits::kMaxShaderValues + 5; ++i)
            values[QString::asprintf("u%06d", i)] = QJsonArray{1.0};
        json["shaderValues"] = values;
        const SceneFileRead capped = parseSceneFile(QJsonDocument(json).toJson(), QDir(), "x");
        QCOMPARE(int(capped.file->scene.shaderValues.size()), limits::kMaxShaderValues);
        QVERIFY2(capped.ignored.join("; ").contains("5 more than the 16384 kept"),
                 qPrintable(capped.ignored.join("; ")));
    }

    void missingFilesAndFoldersAreNamed()
    {
        QCOMPARE(readSceneFile("/nowhere/a.json").error, QString("/nowhere/a.json: no such file"));
        QCOMPARE(readSceneFile("/tmp").error,
                 QString("/tmp: not a regular file (a folder, a device or a pipe)"));
    }

    void newerAndUnknownPartsAreListed()
    {
        QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(SceneFile{}, QDir())).object();
        json["version"] = 7;
        json["hologram"] = QJsonObject{{"on", true}};
        json["program"] = QJsonObject{{"vertex", 12}};
        QJsonArray objects = json["objects"].toArray();
        QJsonObject first = objects[0].toObject();
        QJsonObject material = first["material"].toObject();
        material["shininess"] = 77;
        first["material"] = material;
        objects[0] = first;
        json["objects"] = objects;
        const SceneFileRead read = parseSceneFile(QJsonDocument(json).toJson(), QDir(), "new.json");
        QVERIFY(read.file);
        QCOMPARE(read.file->scene.objects[0].material.shininess, 77.0f); // what it knows is used
        QCOMPARE(read.ignored.size(), 3);
        QVERIFY(read.ignored[0].startsWith("version 7 (newer"));
        QVERIFY(read.ignored.join(' ').contains("hologram (unknown field)"));
        QVERIFY(read.ignored.join(' ').contains("program (needs vertex and fragment"));
    }

    // A lesson where a scene is asked for (a lesson step naming a lesson file, --scene
    // lesson.json): refused as a lesson, not drawn as the default scene with exit 0.
    void aLessonIsNoScene()
    {
        const SceneFileRead read = parseSceneFile(
            R"({"format": "lightbench-lesson", "version": 1, "steps": []})", QDir(), "l.json");
        QVERIFY(!read.file);
        QCOMPARE(read.error,
                 QString("l.json: a lesson file, not a scene file (open it as a lesson)"));
    }

    // A program over the 1 MiB a shader may have is refused as too long (it was "needs vertex
    // and fragment sources as strings", which they were).
    void aProgramTooLongIsSaidToBeTooLong()
    {
        QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(SceneFile{}, QDir())).object();
        json["program"] =
            QJsonObject{{"vertex", QString(1100000, 'x')}, {"fragment", "void main() {}"}};
        const SceneFileRead read = parseSceneFile(QJsonDocument(json).toJson(), QDir(), "big.json");
        QVERIFY(read.file && !read.file->program);
        QVERIFY2(read.ignored.join('|').contains(
                     "program (the vertex shader has 1100000 characters, more than a shader may "
                     "have (1048576))"),
                 qPrintable(read.ignored.join('|')));
    }

    // Unknown fields' names are the file's: shown escaped (issue 49: a name with ESC [2J
    // cleared the terminal, one with a line break made a line of its own, U+202E reversed
    // what followed); a lesson's too.
    void namesOfUnknownFieldsAreEscaped()
    {
        QJsonObject json = QJsonDocument::fromJson(sceneFileBytes(SceneFile{}, QDir())).object();
        json[QString("\x1b[2J\x1b]0;owned\x07")] = 1;
        json[QString("a\nlightbench: all passed")] = 2;
        json[QString(QChar(0x202e)) + "evil"] = 3;
        const SceneFileRead read = parseSceneFile(QJsonDocument(json).toJson(), QDir(), "x.json");
        QVERIFY(read.file);
        const QString said = read.ignored.join('|');
        for (const QChar c : said)
            QVERIFY2(c.unicode() >= 0x20 && c.unicode() != 0x7f && c.unicode() != 0x202e,
                     qPrintable(said));
        QVERIFY2(said.contains("\\x1b[2J") && said.contains("a\\nlightbench") &&
                     said.contains("\\u202eevil"),
                 qPrintable(said));
        const LessonRead lesson = parseLesson(
            QJsonDocument(
                QJsonObject{{"format", "lightbench-lesson"},
                            {"version", 1},
                            {"steps", QJsonArray{QJsonObject{
                                          {"scene", QJsonObject{{QString("t\x1b[31m"), 1}}}}}}})
                .toJson(),
            QDir(), "l.json");
        QVERIFY2(lesson.ignored.join('|').contains("\\x1b[31m"),
                 qPrintable(lesson.ignored.join('|')));
    }

    void thousandsOfMangledFilesNeverCrash()
    {
        QRandomGenerator rng(20261122);
        const QByteArray good = sceneFileBytes(sampleFile(QDir("/tmp")), QDir("/tmp"));
        const QJsonObject tree = QJsonDocument::fromJson(good).object();
        int opened = 0, refused = 0, listed = 0;
        for (int i = 0; i < 4000; ++i) {
            QByteArray bytes;
            if (i % 4 == 0) { // bytes: flips, cuts, insertions
                bytes = good;
                for (int k = 0, n = 1 + int(rng.bounded(8)); k < n; ++k) {
                    const int at = int(rng.bounded(bytes.size()));
                    switch (rng.bounded(3)) {
                    case 0:
                        bytes[at] = char(rng.bounded(256));
                        break;
                    case 1:
                        bytes.truncate(at);
                        break;
                    default:
                        bytes.insert(at, "[{\"\":-1e999}]");
                    }
                    if (bytes.isEmpty())
                        break;
                }
            } else { // structure: values replaced, keys removed or added, several times
                QJsonValue v = tree;
                for (int k = 0, n = 1 + int(rng.bounded(6)); k < n; ++k)
                    v = mangle(v, rng, 0);
                bytes = v.isObject() ? QJsonDocument(v.toObject()).toJson()
                                     : QJsonDocument(QJsonArray{v}).toJson();
            }
            const SceneFileRead read = parseSceneFile(bytes, QDir("/tmp"), "m.json");
            if (!read.file) {
                QVERIFY(!read.error.isEmpty());
                ++refused;
                continue;
            }
            ++opened;
            listed += read.ignored.isEmpty() ? 0 : 1;
            const QString bad = outsideLimits(read.file->scene);
            QVERIFY2(bad.isEmpty(), qPrintable(bad + " in\n" + QString::fromUtf8(bytes)));
            // What was read saves and reads back as itself.
            const SceneFileRead again =
                parseSceneFile(sceneFileBytes(*read.file, QDir("/tmp")), QDir("/tmp"), "again");
            QVERIFY(again.file && again.file->scene == read.file->scene);
            QVERIFY(again.ignored.isEmpty());
        }
        qInfo("4000 mangled files: %d opened (%d with a list of what was ignored), %d refused",
              opened, listed, refused);
        QVERIFY(opened > 1000 && refused > 100 && listed > 1000);
    }
};

QTEST_APPLESS_MAIN(TestSceneFile)
#include "test_scene_file.moc"
