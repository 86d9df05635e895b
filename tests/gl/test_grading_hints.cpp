// Issue 33, part 3, "say what is wrong": the grading child (--grade-one) on the samples and
// the example exercise's known mistakes. The reflection-sign and normal-matrix samples get
// their mistake's name, the correct one none; student-written samples of other listed
// mistakes (tests/data/mistakes) get theirs; samples whose mistake the exercise does not list
// (a shininess of 30, 100 or 200, the light's colour twice, the light direction not
// normalised) get none.
// Each listed mistake's own program, submitted, is found as itself. An exercise whose mistake
// does not build or loops stops the batch with its status; a built-in mistake is drawn by the
// built-in program with its switches.
#include "presets.h"
#include "program_run.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <functional>

namespace {

const QString kData = QStringLiteral(LB_TEST_DATA);
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

QByteArray readBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

using Run = ProgramRun;

Run run(const QStringList &args)
{
    return runProgram(LIGHTBENCH_EXE, args, 300000);
}

QJsonObject gradeOne(const QString &submission, const QString &exercise = kExercise)
{
    const Run r = run({"--grade-one", submission, "--exercise", exercise});
    return QJsonDocument::fromJson(r.out.trimmed()).object();
}

QJsonObject exampleJson()
{
    return QJsonDocument::fromJson(readBytes(kExercise)).object();
}

} // namespace

class TestGradingHints : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    // The example exercise with `cases` cases and `change` applied to its section.
    QString exerciseFile(const QString &name, int cases,
                         const std::function<void(QJsonObject &)> &change = {})
    {
        QJsonObject o = exampleJson();
        QJsonObject e = o["exercise"].toObject();
        QJsonObject g = e["grading"].toObject();
        g["cases"] = cases;
        e["grading"] = g;
        if (change)
            change(e);
        o["exercise"] = e;
        const QString path = m_dir.filePath(name + ".json");
        return write(path, QJsonDocument(o).toJson()) ? path : QString();
    }

private slots:
    void samplesGetTheRightHint_data()
    {
        QTest::addColumn<QString>("submission");
        QTest::addColumn<QString>("mistake"); // empty: no hint
        QTest::newRow("correct") << kData + "/grading/correct"
                                 << "";
        QTest::newRow("reflect_sign") << kData + "/grading/reflect_sign.frag"
                                      << "reflection sign";
        QTest::newRow("normal_matrix") << kData + "/grading/normal_matrix.vert"
                                       << "normal matrix";
        const QString m = kData + "/mistakes/";
        QTest::newRow("per_vertex") << m + "per_vertex.vert"
                                    << "per vertex";
        QTest::newRow("no_specular") << m + "no_specular.frag"
                                     << "specular term missing";
        QTest::newRow("no_ambient") << m + "no_ambient.frag"
                                    << "ambient term missing";
        QTest::newRow("blinn") << m + "blinn.frag"
                               << "Blinn's H";
        QTest::newRow("light_model_view") << m + "light_model_view.frag"
                                          << "light transformed again";
        // V's sign wrong draws what R's sign wrong draws, pixel for pixel: the same hint,
        // which names both.
        QTest::newRow("view_sign") << m + "view_sign.frag"
                                   << "reflection sign";
        // Not listed: no hint, however they fail. A highlight too small is no highlight
        // missing (the specular term's pixels tell them apart).
        QTest::newRow("shininess (unlisted)") << m + "shininess.frag"
                                              << "";
        QTest::newRow("shininess 100 (unlisted)") << m + "shininess_100.frag"
                                                  << "";
        QTest::newRow("shininess 200 (unlisted)") << m + "shininess_200.frag"
                                                  << "";
        QTest::newRow("light_colour_twice (unlisted)") << m + "light_colour_twice.frag"
                                                       << "";
        QTest::newRow("unnormalised_light (unlisted)") << m + "unnormalised_light.frag"
                                                       << "";
    }
    void samplesGetTheRightHint()
    {
        QFETCH(QString, submission);
        QFETCH(QString, mistake);
        const QJsonObject r = gradeOne(submission);
        QCOMPARE(r["status"].toString(), QString("graded"));
        int passed = 0;
        double share = 0;
        const QJsonArray cases = r["cases"].toArray();
        for (const QJsonValue &c : cases) {
            passed += c["passed"].toBool();
            share += c["shareWithin"].toDouble();
        }
        const QJsonObject m = r["mistake"].toObject();
        // The figures behind the rule, for the README and bench/README.md.
        qInfo("%s: %d/%lld passed, mean share %.4f against the reference; mistake %s at %.4f",
              qPrintable(QFileInfo(submission).completeBaseName()), passed, cases.size(),
              share / double(std::max<qsizetype>(1, cases.size())),
              m.isEmpty() ? "none" : qPrintable(m["name"].toString()), m["shareWithin"].toDouble());
        if (mistake.isEmpty()) {
            QVERIFY2(m.isEmpty(), qPrintable(m["name"].toString()));
            // Unlisted mistakes still fail: the hint's absence is not a pass.
            QCOMPARE(passed == cases.size(), QTest::currentDataTag() == QString("correct"));
            return;
        }
        QVERIFY(passed < cases.size());
        QCOMPARE(m["name"].toString(), mistake);
        const QJsonArray listed = exampleJson()["exercise"].toObject()["mistakes"].toArray();
        const int index = m["index"].toInt();
        QVERIFY(index >= 0 && index < listed.size());
        QCOMPARE(listed[index]["name"].toString(), mistake);
        QCOMPARE(m["hint"].toString(), listed[index]["hint"]["en"].toString());
        QVERIFY(m["shareWithin"].toDouble() >= 0.97);
    }

    // Each listed mistake's own program, submitted as a student would, is found as itself:
    // no two of them are so alike that one hides the other.
    void eachListedMistakeFindsItself()
    {
        QVERIFY(m_dir.isValid());
        const QJsonObject e = exampleJson()["exercise"].toObject();
        const QJsonArray listed = e["mistakes"].toArray();
        QCOMPARE(listed.size(), 7);
        const QString exercise = exerciseFile("six-cases", 6);
        for (int i = 0; i < listed.size(); ++i) {
            const QJsonObject m = listed[i].toObject();
            const QString stem = m_dir.filePath(QString("listed%1").arg(i));
            for (const char *stage : {"vertex", "fragment"}) {
                const QString text =
                    m.contains(stage) ? m[stage].toString() : e["reference"][stage].toString();
                QVERIFY(
                    write(stem + (QString(stage) == "vertex" ? ".vert" : ".frag"), text.toUtf8()));
            }
            const QJsonObject r = gradeOne(stem + ".frag", exercise);
            QCOMPARE(r["status"].toString(), QString("graded"));
            QVERIFY2(r["mistake"]["index"].toInt(-1) == i,
                     qPrintable(m["name"].toString() + " found as " +
                                r["mistake"]["name"].toString("nothing")));
            QCOMPARE(r["mistake"]["shareWithin"].toDouble(), 1.0);
        }
    }

    // A mistake that does not build, or that the trial refuses (an endless loop), is the
    // exercise's fault: the child says which, and the batch stops with exit 2 as for a
    // reference that does not build. A submission that passes draws no mistake.
    void aBrokenMistakeStopsTheBatch()
    {
        const QString broken = exerciseFile("broken", 4, [](QJsonObject &e) {
            QJsonArray list = e["mistakes"].toArray();
            QJsonObject m = list[1].toObject();
            m["fragment"] = "void main() { gl_FragColor = vec4(1.0) }\n"; // no ';'
            list[1] = m;
            e["mistakes"] = list;
        });
        QJsonObject r = gradeOne(kData + "/grading/reflect_sign.frag", broken);
        QCOMPARE(r["status"].toString(), QString("mistake does not build"));
        QVERIFY2(r["diagnostic"].toString().startsWith("mistake 1 (reflection sign) fragment:1:"),
                 qPrintable(r["diagnostic"].toString()));
        QVERIFY(!r.contains("mistake"));
        QCOMPARE(gradeOne(kData + "/grading/correct", broken)["status"].toString(),
                 QString("graded"));
        const Run batch = run({"--grade", kData + "/grading/reflect_sign.frag",
                               kData + "/grading/reflect_sign.vert", "--exercise", broken});
        QCOMPARE(batch.exitCode, 2);
        QVERIFY2(batch.err.contains("mistake does not build: mistake 1 (reflection sign)"),
                 batch.err.constData());

        const QString loops = exerciseFile("loops", 4, [](QJsonObject &e) {
            QJsonArray list = e["mistakes"].toArray();
            QJsonObject m = list[0].toObject();
            m.remove("vertex");
            m["fragment"] = "precision mediump float;\nvoid main() {\n  for (;;) {}\n"
                            "  gl_FragColor = vec4(1.0);\n}\n";
            list[0] = m;
            e["mistakes"] = list;
        });
        r = gradeOne(kData + "/grading/normal_matrix.vert", loops);
        QCOMPARE(r["status"].toString(), QString("mistake refused"));
        QVERIFY2(r["diagnostic"].toString().startsWith("mistake 0 (normal matrix) fragment:3:"),
                 qPrintable(r["diagnostic"].toString()));
    }

    // A built-in mistake: the built-in program with the mistake's switches draws it. Against
    // a built-in Phong reference, the built-in Gouraud program's text submitted as the
    // student's is "per vertex"; a mistake of the switches it does not make is not said.
    void aBuiltInMistakeIsDrawnByTheBuiltInProgram()
    {
        const QString exercise = exerciseFile("built-in", 4, [](QJsonObject &e) {
            e["reference"] =
                QJsonObject{{"builtIn", QJsonObject{{"shading", "phong"}, {"specular", "blinn"}}}};
            e["mistakes"] = QJsonArray{
                QJsonObject{{"name", "no ambient"},
                            {"hint", "Add the ambient term."},
                            {"builtIn", QJsonObject{{"terms", QJsonObject{{"ambient", false}}}}}},
                QJsonObject{{"name", "per vertex"},
                            {"hint", "Light each fragment."},
                            {"builtIn", QJsonObject{{"shading", "gouraud"}}}}};
        });
        const QString stem = m_dir.filePath("gouraud");
        QVERIFY(write(stem + ".vert", lb::builtInPreset(true).vertexSource().toUtf8()));
        QVERIFY(write(stem + ".frag", lb::builtInPreset(true).fragmentSource().toUtf8()));
        const QJsonObject r = gradeOne(stem + ".vert", exercise);
        QCOMPARE(r["status"].toString(), QString("graded"));
        QVERIFY2(r["mistake"]["name"].toString() == "per vertex",
                 QJsonDocument(r).toJson(QJsonDocument::Compact).constData());
        QCOMPARE(r["mistake"]["index"].toInt(), 1);
    }
};

QTEST_MAIN(TestGradingHints)
#include "test_grading_hints.moc"
