// Lesson files: what is saved opens as the same lesson (inline scenes and scene files named
// relative to it); captions per language with English as the fallback; broken lessons and
// broken steps are named, never a crash, and what they name is bounded.
#include "lesson.h"
#include "safe_write.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace lb;

namespace {

QString write(const QDir &dir, const QString &name, const QByteArray &bytes)
{
    const QString path = dir.filePath(name);
    return writeFileSafely(path, bytes).isEmpty() ? path : QString();
}

QByteArray json(const QJsonObject &o)
{
    return QJsonDocument(o).toJson();
}

QJsonObject lessonWith(const QJsonArray &steps)
{
    return {{"format", "lightbench-lesson"}, {"version", 1}, {"steps", steps}};
}

} // namespace

class TestLesson : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void localizedFallsBackToEnglish()
    {
        const LocalizedText text{{"en", "Light"}, {"pt", "Luz"}, {"de", "Licht"}};
        QCOMPARE(localized(text, "pt"), QString("Luz"));
        QCOMPARE(localized(text, "pt_PT"), QString("Luz"));
        QCOMPARE(localized(text, "de_DE.UTF-8"), QString("Licht"));
        QCOMPARE(localized(text, "fr"), QString("Light"));
        QCOMPARE(localized(text, ""), QString("Light"));
        QCOMPARE(localized({{"pt", "Luz"}}, "de"), QString("Luz")); // no English: what there is
        QCOMPARE(localized({}, "de"), QString());
    }

    // The language as a lesson names it: the one chosen, else the system's (LANG; the C and
    // POSIX locales name none, and the window would write captions under "C", which no lesson
    // file takes: English), whatever the application's default QLocale is.
    void lessonLanguageIsALanguageCode()
    {
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        const QString system = QLocale::system().name().section('_', 0, 0);
        QCOMPARE(lessonLanguage(), system.size() == 2 ? system : QString("en"));
        setLessonLanguage("pt");
        QCOMPARE(lessonLanguage(), QString("pt"));
        setLessonLanguage({});
        QCOMPARE(lessonLanguage(), system.size() == 2 ? system : QString("en"));
        QLocale::setDefault(before);
    }

    void savedLessonOpensTheSame()
    {
        QDir dir(m_dir.path());
        QVERIFY(dir.mkpath("scenes"));
        SceneFile referenced;
        referenced.scene.objects[0].material.shininess = 77;
        QCOMPARE(writeSceneFile(dir.filePath("scenes/shiny.json"), referenced), QString());

        Lesson lesson;
        lesson.title = {{"en", "Lighting"}, {"pt", "Iluminação"}};
        LessonStep inlineStep;
        inlineStep.title = {{"en", "Gouraud"}};
        inlineStep.caption = {{"en", "Per vertex."}, {"de", "Pro Vertex."}};
        inlineStep.scene.scene.shading.shading = Shading::Gouraud;
        inlineStep.scene.scene.objects[0].meshPath = dir.filePath("meshes/bunny.ply");
        inlineStep.scene.program =
            ProgramText{plainText("mine"), "void main(){}", "void main(){}", true};
        inlineStep.panel = "shading";
        inlineStep.highlight = "shading.shading";
        LessonStep fileStep;
        fileStep.title = {{"en", "Shiny"}};
        fileStep.scene = referenced;
        fileStep.scenePath = dir.filePath("scenes/shiny.json");
        lesson.steps = {inlineStep, fileStep};

        const QString path = dir.filePath("lesson.json");
        QCOMPARE(writeLessonFile(path, lesson), QString());
        // The file names the scene file relative to itself and holds the other inline.
        const QJsonObject root = QJsonDocument::fromJson([&] {
                                     QFile f(path);
                                     f.open(QIODevice::ReadOnly);
                                     return f.readAll();
                                 }())
                                     .object();
        const QJsonArray steps = root["steps"].toArray();
        QCOMPARE(steps[1].toObject()["scene"].toString(), QString("scenes/shiny.json"));
        QCOMPARE(steps[0].toObject()["title"].toString(), QString("Gouraud")); // English alone
        QVERIFY(steps[0].toObject()["caption"].isObject());
        QCOMPARE(steps[0]
                     .toObject()["scene"]
                     .toObject()["objects"]
                     .toArray()[0]
                     .toObject()["mesh"]
                     .toString(),
                 QString("meshes/bunny.ply"));

        const LessonRead read = readLessonFile(path);
        QVERIFY2(read.lesson, qPrintable(read.error));
        QVERIFY2(read.ignored.isEmpty(), qPrintable(read.ignored.join("; ")));
        QVERIFY(read.stepErrors.isEmpty());
        const Lesson &back = *read.lesson;
        QCOMPARE(back.title, lesson.title);
        QCOMPARE(int(back.steps.size()), 2);
        QCOMPARE(back.steps[0].caption, inlineStep.caption);
        QCOMPARE(back.steps[0].panel, QString("shading"));
        QCOMPARE(back.steps[0].highlight, QString("shading.shading"));
        QVERIFY(back.steps[0].scene.scene == inlineStep.scene.scene);
        QVERIFY(back.steps[0].scene.program == inlineStep.scene.program);
        QVERIFY(back.steps[0].scenePath.isEmpty());
        QCOMPARE(back.steps[1].scene.scene.objects[0].material.shininess, 77.0f);
        QCOMPARE(back.steps[1].scenePath, QDir::cleanPath(dir.filePath("scenes/shiny.json")));

        // Saved elsewhere: the reference still reaches the same file.
        QVERIFY(dir.mkpath("elsewhere/deeper"));
        const QString moved = dir.filePath("elsewhere/deeper/lesson.json");
        QCOMPARE(writeLessonFile(moved, back), QString());
        const LessonRead again = readLessonFile(moved);
        QVERIFY2(again.lesson && again.stepErrors.isEmpty(),
                 qPrintable(again.error + again.stepErrors.join("; ")));
        QCOMPARE(again.lesson->steps[1].scene.scene.objects[0].material.shininess, 77.0f);
    }

    // Bad input: each case names what is wrong, and none crashes.
    void brokenLessonsAreNamed_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("said");
        QTest::newRow("not JSON") << QByteArray("{\"steps\": [") << "not a lesson file:";
        QTest::newRow("empty") << QByteArray() << "not a lesson file:";
        QTest::newRow("array") << QByteArray("[1, 2]") << "not a lesson file";
        QTest::newRow("a scene file")
            << QByteArray(R"({"format": "lightbench-scene", "version": 3})") << "a scene file";
        QTest::newRow("no steps") << json(lessonWith({})) << "has no steps";
        QTest::newRow("steps not a list")
            << QByteArray(R"({"format": "lightbench-lesson", "steps": 3})") << "has no steps";
        QJsonArray many;
        for (int i = 0; i <= kMaxLessonSteps; ++i)
            many.append(QJsonObject{{"scene", QJsonObject{}}});
        QTest::newRow("too many steps") << json(lessonWith(many)) << "steps; a lesson may have";
    }
    void brokenLessonsAreNamed()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, said);
        const LessonRead read = parseLesson(bytes, QDir(m_dir.path()), "l.json");
        QVERIFY(!read.lesson);
        QVERIFY2(read.error.startsWith("l.json: ") && read.error.contains(said),
                 qPrintable(read.error));
    }

    // A broken step keeps its place with its reason; the others are read.
    void brokenStepsKeepTheirPlace()
    {
        QDir dir(m_dir.path());
        QVERIFY(::mkfifo(qPrintable(dir.filePath("fifo.json")), 0600) == 0);
        QVERIFY(!write(dir, "garbage.json", "not json at all").isEmpty());
        const QJsonArray steps{
            QJsonObject{{"title", "good"}, {"scene", QJsonObject{}}},
            QJsonObject{{"title", "missing"}, {"scene", "nowhere.json"}},
            QJsonObject{{"title", "fifo"}, {"scene", "fifo.json"}},
            QJsonObject{{"title", "garbage"}, {"scene", "garbage.json"}},
            QJsonObject{{"title", "no scene"}},
            QJsonValue(42),
            QJsonObject{{"title", 7},
                        {"caption", QJsonObject{{"pt", "ok"}, {"x", "no code"}, {"de", 3}}},
                        {"panel", "kitchen"},
                        {"highlight", "light.nowhere"},
                        {"scene", QJsonObject{{"material", "shiny"}}}},
            QJsonObject{{"caption", QString(kMaxLessonTextCharacters + 1, 'x')},
                        {"scene", QJsonObject{}}}};
        const LessonRead read = parseLesson(json(lessonWith(steps)), dir, "l.json");
        QVERIFY2(read.lesson, qPrintable(read.error));
        const std::vector<LessonStep> &s = read.lesson->steps;
        QCOMPARE(int(s.size()), 8);
        QVERIFY(s[0].error.isEmpty());
        QVERIFY2(s[1].error.startsWith("step 2: ") && s[1].error.contains("no such file"),
                 qPrintable(s[1].error));
        QVERIFY2(s[2].error.startsWith("step 3: ") && s[2].error.contains("not a regular file"),
                 qPrintable(s[2].error));
        QVERIFY2(s[3].error.contains("not a scene file"), qPrintable(s[3].error));
        QVERIFY2(s[4].error.contains("no scene"), qPrintable(s[4].error));
        QVERIFY2(s[5].error.contains("not an object"), qPrintable(s[5].error));
        QCOMPARE(read.stepErrors.size(), 5);
        QVERIFY(s[6].error.isEmpty()); // what is wrong in it is left out and named
        QVERIFY(s[6].title.isEmpty() && s[6].panel.isEmpty() && s[6].highlight.isEmpty());
        QCOMPARE(s[6].caption, LocalizedText({{"pt", "ok"}}));
        const QString ignored = read.ignored.join("\n");
        for (const char *named : {"step 7: title (not text)", "step 7: caption.x (not a language",
                                  "step 7: caption.de (not text)", "step 7: panel (\"kitchen\"",
                                  "step 7: highlight (\"light.nowhere\"",
                                  "step 7: scene: ", "step 8: caption (4001 characters"})
            QVERIFY2(ignored.contains(named), qPrintable(named + QString(" in:\n") + ignored));
    }

    // The same big scene file named on every step counts every time against one limit.
    void sceneFilesShareTheLessonsLimit()
    {
        QDir dir(m_dir.path());
        const QString big = write(dir, "big.json", "{}" + QByteArray(1024 * 1024, ' '));
        QVERIFY(!big.isEmpty());
        QJsonArray steps;
        for (int i = 0; i < 5; ++i)
            steps.append(QJsonObject{{"scene", "big.json"}});
        const QByteArray bytes = json(lessonWith(steps));
        const LessonRead read = parseLesson(bytes, dir, "l.json", 3 * 1024 * 1024);
        QVERIFY(read.lesson);
        QCOMPARE(read.stepErrors.size(), 3);
        QVERIFY2(read.lesson->steps[3].error.contains("past what is left of the lesson's limit"),
                 qPrintable(read.lesson->steps[3].error));
    }

    // Saving onto a FIFO (or a folder) is refused, and nothing waits for a reader.
    void savingOntoAFifoIsRefused()
    {
        const QString fifo = QDir(m_dir.path()).filePath("save.fifo");
        QVERIFY(::mkfifo(qPrintable(fifo), 0600) == 0);
        Lesson lesson;
        lesson.steps.resize(1);
        const QString error = writeLessonFile(fifo, lesson);
        QVERIFY2(error.startsWith(fifo + ": "), qPrintable(error));
        QVERIFY(QFileInfo(fifo).isSymLink() || !QFileInfo(fifo).isFile()); // still the FIFO
        QVERIFY(!writeLessonFile(m_dir.path(), lesson).isEmpty());
    }

    void theBuiltInExampleStaysBuiltIn()
    {
        Lesson lesson;
        LessonStep step;
        step.scenePath = ":/examples/terms.json";
        lesson.steps = {step};
        const QJsonObject root =
            QJsonDocument::fromJson(lessonFileBytes(lesson, QDir(m_dir.path()))).object();
        QCOMPARE(root["steps"].toArray()[0].toObject()["scene"].toString(),
                 QString(":/examples/terms.json"));
    }
};

QTEST_GUILESS_MAIN(TestLesson)
#include "test_lesson.moc"
