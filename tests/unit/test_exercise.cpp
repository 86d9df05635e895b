// Exercise scenes (exercise.h): the "exercise" section read, written back and named where it
// is wrong; the grading cases drawn from a seed (the same seed, the same cases; case k the
// same however many are asked for; case 0 the exercise as it is; only what "vary" names
// varies).
#include "exercise.h"
#include "scene_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

using namespace lb;

namespace {

Exercise sample()
{
    Exercise e;
    e.title = {{"en", "Lighting"}, {"de", "Beleuchtung"}};
    e.task = {{"en", "Write the fragment shader."}};
    e.reference.vertex = "void main() { gl_Position = vec4(0.0); }";
    e.reference.fragment = "void main() { gl_FragColor = vec4(1.0); }";
    e.grading.cases = 7;
    e.grading.size = QSize(200, 100);
    e.grading.tolerance = 3;
    e.grading.passShare = 0.95;
    e.grading.vary = unsigned(Vary::Light) | unsigned(Vary::Scale);
    return e;
}

} // namespace

class TestExercise : public QObject
{
    Q_OBJECT
private slots:
    void roundTripsThroughASceneFile()
    {
        SceneFile f;
        f.exercise = sample();
        f.program = ProgramText{plainText("start"), "void main() {}", "void main() {}", false};
        const SceneFileRead read =
            parseSceneFile(sceneFileBytes(f, QDir("/tmp")), QDir("/tmp"), "lesson.json");
        QVERIFY2(read.ignored.isEmpty(), qPrintable(read.ignored.join(", ")));
        QVERIFY(read.exerciseError.isEmpty());
        QVERIFY(read.file->exercise);
        const Exercise &e = *read.file->exercise;
        QCOMPARE(e.title, sample().title);
        QCOMPARE(e.task, sample().task);
        QCOMPARE(localized(e.title, "de_DE.UTF-8"), QString("Beleuchtung"));
        QCOMPARE(localized(e.title, "pt"), QString("Lighting")); // English when there is no pt
        QCOMPARE(e.reference.fragment, sample().reference.fragment);
        QCOMPARE(e.grading.cases, 7);
        QCOMPARE(e.grading.size, QSize(200, 100));
        QCOMPARE(e.grading.tolerance, 3);
        QCOMPARE(e.grading.passShare, 0.95);
        QCOMPARE(e.grading.vary, unsigned(Vary::Light) | unsigned(Vary::Scale));
        // A built-in reference keeps its choices.
        Exercise b = sample();
        b.reference = ExerciseReference{};
        b.reference.shading = Shading::Gouraud;
        b.reference.specular = SpecularModel::Blinn;
        const ExerciseRead back = readExercise(exerciseJson(b), nullptr);
        QVERIFY(back.exercise && back.exercise->reference.builtIn());
        QCOMPARE(back.exercise->reference.shading, Shading::Gouraud);
        QCOMPARE(back.exercise->reference.specular, SpecularModel::Blinn);
    }

    // The title and the task in the course's languages (issue 31): a string is English; an
    // object gives one per language. Bad input tried: a number, an array, a code too long,
    // a task over 8000 characters: each left out and named, the rest kept.
    void titleAndTaskPerLanguage()
    {
        QJsonObject json = exerciseJson(sample());
        QCOMPARE(json["task"].toString(), QString("Write the fragment shader.")); // only English
        QCOMPARE(json["title"].toObject()["de"].toString(), QString("Beleuchtung"));
        json["title"] = QJsonObject{
            {"en", "Lighting"}, {"pt", "Iluminação"}, {"de", 5}, {"a-very-long-code", "x"}};
        json["task"] = QJsonObject{{"en", QString(8001, 'x')}, {"pt", "Escreva o shader."}};
        QStringList ignored;
        const ExerciseRead read = readExercise(json, &ignored);
        QVERIFY(read.exercise);
        QCOMPARE(read.exercise->title, (LocalizedText{{"en", "Lighting"}, {"pt", "Iluminação"}}));
        QCOMPARE(read.exercise->task, (LocalizedText{{"pt", "Escreva o shader."}}));
        QCOMPARE(ignored.size(), 3);
        QVERIFY2(ignored.join("|").contains("exercise.title.de (not text)"),
                 qPrintable(ignored.join("|")));
        QVERIFY(ignored.join("|").contains("exercise.task.en (8001 characters; at most 8000)"));
        QVERIFY(
            ignored.join("|").contains("exercise.title.a-very-long-code (not a language code)"));
        json["title"] = QJsonArray{"Lighting"};
        ignored.clear();
        QVERIFY(readExercise(json, &ignored).exercise->title.isEmpty());
        QVERIFY(ignored.join("|").contains("exercise.title (not text)"));
    }

    void badFieldsAreNamed()
    {
        QJsonObject json = exerciseJson(sample());
        QJsonObject grading = json["grading"].toObject();
        grading["cases"] = -5;
        grading["tolerance"] = "two";
        grading["size"] = QJsonArray{320};
        grading["vary"] = QJsonArray{"light", "weather"};
        json["grading"] = grading;
        json["solution"] = true;
        QStringList ignored;
        const ExerciseRead read = readExercise(json, &ignored);
        QVERIFY(read.exercise);
        QCOMPARE(read.exercise->grading.cases, 1); // clamped
        QCOMPARE(read.exercise->grading.tolerance, GradingSpec{}.tolerance);
        QCOMPARE(read.exercise->grading.size, GradingSpec{}.size);
        QCOMPARE(read.exercise->grading.vary, unsigned(Vary::Light));
        const QString all = ignored.join('\n');
        for (const char *path :
             {"exercise.grading.cases (out of range, clamped)", "exercise.grading.tolerance",
              "exercise.grading.size", "exercise.grading.vary (no such parameter 'weather'",
              "exercise.solution (unknown field)"})
            QVERIFY2(all.contains(QLatin1String(path)), qPrintable(all));

        // Nothing to grade against: an error, not an exercise.
        for (const QJsonValue &bad :
             {QJsonValue(QJsonObject{{"title", "x"}}),
              QJsonValue(QJsonObject{{"reference", QJsonObject{{"vertex", "void main(){}"}}}}),
              QJsonValue(5)}) {
            const ExerciseRead r = readExercise(bad, nullptr);
            QVERIFY(!r.error.isEmpty());
            // Kept as it was, so that a scene saved meanwhile loses none of it.
            QVERIFY(r.exercise && r.exercise->unread == bad);
        }
        SceneFile f;
        const QJsonObject draft{{"title", "Lighting"},
                                {"reference", QJsonObject{{"vertex", "void main(){}"}}}};
        QJsonObject root = QJsonDocument::fromJson(sceneFileBytes(f, QDir("/tmp"))).object();
        root["exercise"] = draft;
        const SceneFileRead draftRead =
            parseSceneFile(QJsonDocument(root).toJson(), QDir("/tmp"), "draft.json");
        QVERIFY(draftRead.exerciseError.contains("needs both"));
        QVERIFY(draftRead.ignored.join(' ').contains("kept as it is"));
        const QJsonObject again =
            QJsonDocument::fromJson(sceneFileBytes(*draftRead.file, QDir("/tmp"))).object();
        QCOMPARE(again["exercise"].toObject(), draft);
    }

    void casesComeFromTheSeed()
    {
        Scene base;
        base.objects.resize(2);
        GradingSpec spec;
        spec.cases = 6;
        const std::vector<Scene> a = gradingCases(base, spec, 7), b = gradingCases(base, spec, 7);
        const std::vector<Scene> other = gradingCases(base, spec, 8);
        QCOMPARE(int(a.size()), 6);
        Scene still = base;
        still.showLight = false;
        QVERIFY(a[0] == still); // the exercise as it is (no marker: it is no program's)
        // Saved with a compare view or normal lines: the cases show the programs alone.
        Scene shown = base;
        shown.compare.mode = CompareMode::Difference;
        shown.objects[0].showNormals = true;
        for (const Scene &s : gradingCases(shown, spec, 7))
            QVERIFY(s.compare.mode == CompareMode::Off && !s.objects[0].showNormals);
        for (int k = 0; k < 6; ++k)
            QVERIFY(a[std::size_t(k)] == b[std::size_t(k)]);
        QVERIFY(!(a[3] == other[3]));
        QVERIFY(!(a[1] == a[2]));
        // Case 3 of 6 is case 3 of 20.
        spec.cases = 20;
        QVERIFY(gradingCases(base, spec, 7)[3] == a[3]);
        // The light stays 2 to 4 units from the origin; scales are non-uniform.
        for (const Scene &s : gradingCases(base, spec, 7)) {
            const float d = glm::length(glm::vec3(s.lights[0].position));
            QVERIFY(s == a[0] || (d >= 2.0f && d <= 4.0f));
        }
    }

    void onlyWhatVaryNamesVaries()
    {
        Scene base;
        GradingSpec spec;
        spec.cases = 5;
        spec.vary = unsigned(Vary::Material);
        for (const Scene &s : gradingCases(base, spec, 3)) {
            QCOMPARE(s.lights[0].position, base.lights[0].position);
            QCOMPARE(s.camera.yawDegrees, base.camera.yawDegrees);
            QCOMPARE(s.objects[0].scale, base.objects[0].scale);
            QCOMPARE(s.shading.projection, base.shading.projection);
        }
        QVERIFY(!(gradingCases(base, spec, 3)[1].objects[0].material == base.objects[0].material));
    }
};

QTEST_MAIN(TestExercise)
#include "test_exercise.moc"
