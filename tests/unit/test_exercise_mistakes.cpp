// An exercise's known mistakes (exercise_mistakes.h): the "mistakes" list read, written back
// unchanged (also through a scene file), bounded, and each bad entry named where it is; a
// built-in mistake's switches set on a case's scene; the matching rule (mistake_match.h) on
// shares at and around its bounds.
#include "exercise.h"
#include "mistake_match.h"
#include "scene_file.h"

#include <QJsonArray>
#include <QTest>

using namespace lb;

namespace {

QJsonObject programReference()
{
    return QJsonObject{{"vertex", "void main() { gl_Position = vec4(0.0); }"},
                       {"fragment", "void main() { gl_FragColor = vec4(1.0); }"}};
}

QJsonObject section(const QJsonValue &mistakes, const QJsonObject &reference = programReference())
{
    return QJsonObject{{"title", "t"}, {"reference", reference}, {"mistakes", mistakes}};
}

QJsonObject goodMistake(const QString &name)
{
    return QJsonObject{{"name", name},
                       {"hint", QJsonObject{{"en", "Use the inverse transpose."},
                                            {"de", "Die transponierte Inverse."}}},
                       {"vertex", "void main() { gl_Position = vec4(1.0); }"}};
}

ExerciseRead read(const QJsonObject &json, QStringList *ignored)
{
    return readExercise(json, ignored);
}

} // namespace

class TestExerciseMistakes : public QObject
{
    Q_OBJECT
private slots:
    void roundTripsThroughASceneFile()
    {
        QJsonArray list{
            goodMistake("normal matrix"),
            QJsonObject{{"name", "per vertex"},
                        {"hint", "Light per fragment."},
                        {"builtIn", QJsonObject{{"shading", "gouraud"},
                                                {"specular", "blinn"},
                                                {"terms", QJsonObject{{"ambient", false}}},
                                                {"normalsByModelView", true},
                                                {"lightFrame", "world"}}}}};
        // A built-in reference: its mistakes may be built-in ones, or whole programs.
        QJsonObject whole = list[0].toObject();
        whole["fragment"] = "void main() { gl_FragColor = vec4(1.0); }";
        list[0] = whole;
        QStringList ignored;
        const ExerciseRead r = read(
            section(list, QJsonObject{{"builtIn", QJsonObject{{"shading", "phong"}}}}), &ignored);
        QVERIFY2(ignored.isEmpty(), qPrintable(ignored.join("; ")));
        QVERIFY(r.error.isEmpty());
        const std::vector<ExerciseMistake> &m = r.exercise->mistakes;
        QCOMPARE(int(m.size()), 2);
        QCOMPARE(m[0].name, QString("normal matrix"));
        QCOMPARE(localized(m[0].hint, "de"), QString("Die transponierte Inverse."));
        QVERIFY(!m[0].isBuiltIn());
        QVERIFY(!m[0].vertex.isEmpty() && !m[0].fragment.isEmpty());
        QVERIFY(m[1].isBuiltIn());
        QCOMPARE(*m[1].builtIn.shading, Shading::Gouraud);
        QCOMPARE(*m[1].builtIn.ambient, false);
        QVERIFY(!m[1].builtIn.diffuse); // unset: the case's own
        // Written back as read, and through a whole scene file.
        QCOMPARE(exerciseJson(*r.exercise)["mistakes"].toArray(), list);
        SceneFile f;
        f.exercise = *r.exercise;
        const SceneFileRead back =
            parseSceneFile(sceneFileBytes(f, QDir("/tmp")), QDir("/tmp"), "exercise.json");
        QVERIFY2(back.ignored.isEmpty(), qPrintable(back.ignored.join(", ")));
        QCOMPARE(exerciseJson(*back.file->exercise)["mistakes"].toArray(), list);
        // An exercise without mistakes writes no list (files from before keep their bytes).
        QVERIFY(!exerciseJson(Exercise{})["mistakes"].isArray());
    }

    // Bad input tried, each named and left out while the good entries stay: an entry that is
    // not an object, a 17th mistake, a hint that is a number, a program that is not text, a
    // built-in with a bad word, no name, a name too long, a program and a built-in at once,
    // neither, an unknown field, a list that is not a list, one stage against a built-in
    // reference.
    void badEntriesAreNamed_data()
    {
        QTest::addColumn<QJsonValue>("mistakes");
        QTest::addColumn<QJsonObject>("reference");
        QTest::addColumn<QString>("named");
        QTest::addColumn<int>("kept");
        const QJsonObject ref = programReference();
        const QJsonObject builtInRef{{"builtIn", QJsonObject{{"shading", "phong"}}}};
        QTest::newRow("not an object") << QJsonValue(QJsonArray{goodMistake("a"), 5}) << ref
                                       << "mistakes[1] (not an object)" << 1;
        QJsonArray seventeen;
        for (int i = 0; i < 17; ++i)
            seventeen.append(goodMistake(QString("m%1").arg(i)));
        QTest::newRow("17th") << QJsonValue(seventeen) << ref
                              << "mistakes[16] (more than 16 mistakes" << 16;
        QJsonObject numberHint = goodMistake("a");
        numberHint["hint"] = 5;
        QTest::newRow("hint a number") << QJsonValue(QJsonArray{numberHint, goodMistake("b")})
                                       << ref << "mistakes[0].hint" << 1;
        QJsonObject notText = goodMistake("a");
        notText["fragment"] = QJsonArray{1, 2};
        QTest::newRow("program not text")
            << QJsonValue(QJsonArray{notText}) << ref << "mistakes[0].fragment (not a shader" << 0;
        QJsonObject badWord{
            {"name", "w"}, {"hint", "h"}, {"builtIn", QJsonObject{{"shading", "toon"}}}};
        QTest::newRow("builtIn bad word")
            << QJsonValue(QJsonArray{badWord}) << builtInRef
            << "mistakes[0].builtIn.shading (not gouraud, phong, flat)" << 1;
        // The built-in program beside a teacher's program draws something unrelated.
        QTest::newRow("builtIn beside a program reference")
            << QJsonValue(QJsonArray{badWord}) << ref
            << "mistakes[0] (a built-in mistake needs a built-in reference" << 0;
        QJsonObject badSwitch{{"name", "w"},
                              {"hint", "h"},
                              {"builtIn", QJsonObject{{"terms", QJsonObject{{"ambient", "no"}}}}}};
        QTest::newRow("builtIn switch not a bool")
            << QJsonValue(QJsonArray{badSwitch}) << builtInRef
            << "mistakes[0].builtIn.terms.ambient (not true or false)" << 1;
        QJsonObject noName = goodMistake("a");
        noName.remove("name");
        QTest::newRow("no name") << QJsonValue(QJsonArray{noName}) << ref << "mistakes[0].name"
                                 << 0;
        QTest::newRow("name too long") << QJsonValue(QJsonArray{goodMistake(QString(201, 'n'))})
                                       << ref << "mistakes[0].name" << 0;
        QJsonObject both = goodMistake("a");
        both["builtIn"] = QJsonObject{};
        QTest::newRow("program and built-in")
            << QJsonValue(QJsonArray{both}) << ref << "mistakes[0] (both a program" << 0;
        QTest::newRow("neither") << QJsonValue(
                                        QJsonArray{QJsonObject{{"name", "a"}, {"hint", "h"}}})
                                 << ref << "mistakes[0] (neither a program" << 0;
        QJsonObject unknown = goodMistake("a");
        unknown["vertx"] = "x";
        QTest::newRow("unknown field")
            << QJsonValue(QJsonArray{unknown}) << ref << "mistakes[0].vertx (unknown field)" << 1;
        QTest::newRow("not a list")
            << QJsonValue("normal matrix") << ref << "mistakes (not a list)" << 0;
        QTest::newRow("one stage, built-in reference")
            << QJsonValue(QJsonArray{goodMistake("a")}) << builtInRef
            << "mistakes[0] (needs both a vertex and a fragment shader" << 0;
    }
    void badEntriesAreNamed()
    {
        QFETCH(QJsonValue, mistakes);
        QFETCH(QJsonObject, reference);
        QFETCH(QString, named);
        QFETCH(int, kept);
        QStringList ignored;
        const ExerciseRead r = read(section(mistakes, reference), &ignored);
        QVERIFY(r.error.isEmpty()); // the exercise itself still grades
        QCOMPARE(int(r.exercise->mistakes.size()), kept);
        const QString all = ignored.join("; ");
        QVERIFY2(all.contains("exercise." + named), qPrintable(all));
    }

    // A built-in mistake applies to the case's scene: only the switches it sets change.
    void builtInMistakeSetsItsSwitches()
    {
        Scene c;
        c.shading.specular = SpecularModel::Phong;
        c.lights[0].frame = LightFrame::Camera;
        ExerciseMistake m;
        m.builtIn.normalsByModelView = true;
        m.builtIn.lightFrame = LightFrame::World;
        m.builtIn.specularTerm = false;
        const Scene s = mistakeScene(c, m);
        QVERIFY(s.shading.normalsByModelView);
        QCOMPARE(s.lights[0].frame, LightFrame::World);
        QVERIFY(!s.shading.terms.specular);
        QVERIFY(s.shading.terms.ambient);
        QCOMPARE(s.shading.specular, SpecularModel::Phong); // unset: the case's
        QCOMPARE(s.shading.shading, c.shading.shading);
        // A program mistake leaves the case alone.
        m.fragment = "void main() {}";
        QVERIFY(mistakeScene(c, m) == c);
    }

    // The rule: at least kMistakeMinShare, and outside the tolerance at most a quarter of
    // what is outside it against the reference; on the pixels the mistake changes, at least
    // kMistakeSignatureShare the mistake's; the best of those that match.
    void matchingRule()
    {
        // A mistake that changes 1000 pixels, all of which the student has as it draws them.
        const auto clear = [](double share) { return MistakeShares{share, 1.0, 1000}; };
        using Shares = std::vector<MistakeShares>;
        QCOMPARE(bestMistake(0.70, {}), -1);
        QCOMPARE(bestMistake(0.70, Shares{clear(0.50), clear(0.99), clear(0.98)}), 1);
        QCOMPARE(bestMistake(0.70, Shares{clear(0.96)}), -1);            // below the share
        QCOMPARE(bestMistake(0.70, Shares{clear(kMistakeMinShare)}), 0); // at it
        // Far better than the reference, not merely better: the reference at 95% leaves 5%
        // outside, so the mistake must leave at most 1.25%.
        QCOMPARE(bestMistake(0.95, Shares{clear(0.985)}), -1);
        QCOMPARE(bestMistake(0.95, Shares{clear(0.99)}), 0);
        // A submission near the reference gets none unless a mistake is nearer still.
        QCOMPARE(bestMistake(0.98, Shares{clear(0.99)}), -1);
        QCOMPARE(bestMistake(0.70, Shares{clear(0.99), clear(0.99)}), 0); // the first of equals
        // Close over the frame, but not where the mistake changes the picture (a highlight
        // too small is no highlight missing): none.
        QCOMPARE(bestMistake(0.85, Shares{{0.98, 0.90, 1000}}), -1);
        QCOMPARE(bestMistake(0.85, Shares{{0.98, kMistakeSignatureShare, 1000}}), 0);
        // A mistake that changes nothing in these cases explains nothing.
        QCOMPARE(bestMistake(0.85, Shares{{1.0, 0.0, 0}}), -1);
        // Cases that failed with nothing outside the tolerance (nothing drawn by either): no
        // failure to explain.
        QCOMPARE(bestMistake(1.0, Shares{clear(1.0)}), -1);
    }
};

QTEST_GUILESS_MAIN(TestExerciseMistakes)
#include "test_exercise_mistakes.moc"
