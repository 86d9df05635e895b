// Grading a class (--grade) as a teacher runs it: the sample submissions in tests/data/grading
// against the example exercise (the sheet's per-fragment lighting task): the correct one
// passes every case, each wrong one fails the cases that expose its mistake, the one that does
// not compile names its line, the endless loop is reported without stalling the batch; the
// CSV and the sheets; the same seed gives the same report; bad input exits 2 naming it.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

namespace {

const QString kData = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

struct Run
{
    int exitCode;
    QByteArray out, err;
    qint64 ms;
};

Run run(const QStringList &args)
{
    QElapsedTimer clock;
    clock.start();
    QProcess p;
    p.start(LIGHTBENCH_EXE, args);
    if (!p.waitForFinished(300000))
        return {-1, {}, "timed out", clock.elapsed()};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError(), clock.elapsed()};
}

// One submission's JSON, as the batch's child prints it.
QJsonObject gradeOne(const QString &submission, const QString &exercise = kExercise)
{
    const Run r = run({"--grade-one", submission, "--exercise", exercise});
    return QJsonDocument::fromJson(r.out.trimmed()).object();
}

QList<QStringList> csvRows(const QString &path)
{
    QFile f(path);
    QList<QStringList> rows;
    if (!f.open(QIODevice::ReadOnly))
        return rows;
    for (const QByteArray &line : f.readAll().split('\n'))
        if (!line.isEmpty())
            rows << QString::fromUtf8(line).split(','); // the fields tested hold no commas
    return rows;
}

bool write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

} // namespace

class TestGrading : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void theSampleClass()
    {
        const QString report = m_dir.filePath("grades.csv");
        const QString sheets = m_dir.filePath("sheets");
        const Run r = run({"--grade", kData + "/correct", kData + "/reflect_sign.vert",
                           kData + "/normal_matrix.frag", kData + "/syntax", kData + "/loop.vert",
                           "--exercise", kExercise, "--report", report, "--sheets", sheets});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        qInfo("five submissions in %lld ms", r.ms);
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 5);
        QVERIFY2(lines[0].startsWith("correct: passed 20/20 cases"), lines[0].constData());
        QVERIFY2(lines[1].startsWith("reflect_sign: failed"), lines[1].constData());
        QVERIFY2(lines[2].startsWith("normal_matrix: failed"), lines[2].constData());
        QVERIFY2(lines[3].startsWith("syntax: does not compile: syntax.frag:26:"),
                 lines[3].constData());
        QVERIFY2(lines[4].startsWith("loop: refused: loop.frag:"), lines[4].constData());

        const QList<QStringList> rows = csvRows(report);
        QCOMPARE(rows.size(), 6);
        QCOMPARE(rows[0], QString("submission,status,cases_passed,cases,worst_difference,"
                                  "mean_share_within,first_diagnostic")
                              .split(','));
        QCOMPARE(rows[1].mid(0, 4), QStringList({"correct", "graded", "20", "20"}));
        QVERIFY(rows[1][4].toInt() <= 2);
        QCOMPARE(rows[2][1], QString("graded"));
        QVERIFY(rows[2][2].toInt() < 20);
        QCOMPARE(rows[4][1], QString("does not compile"));
        QVERIFY(rows[4][6].contains("syntax.frag:26"));
        QCOMPARE(rows[5][1], QString("refused"));

        // One sheet per graded submission: student | reference | heat map, with a title.
        for (const char *name : {"correct", "reflect_sign", "normal_matrix"}) {
            const QImage sheet(QDir(sheets).filePath(QString(name) + ".png"));
            QVERIFY2(!sheet.isNull(), name);
            QVERIFY(sheet.width() > 3 * 320 && sheet.height() > 240);
        }
        QVERIFY(!QFileInfo::exists(QDir(sheets).filePath("syntax.png")));
    }

    // Each wrong answer fails the cases that expose it and passes those that cannot.
    void eachMistakeFailsItsCases()
    {
        const QJsonObject correct = gradeOne(kData + "/correct");
        QCOMPARE(correct["status"].toString(), QString("graded"));
        for (const QJsonValue &c : correct["cases"].toArray())
            QVERIFY2(c["passed"].toBool(), qPrintable(QJsonDocument(c.toObject()).toJson()));

        // The normal matrix is only wrong under a non-uniform scale: case 0 (the exercise as
        // it is, unscaled) passes, the scaled ones fail.
        const QJsonArray normals = gradeOne(kData + "/normal_matrix.vert")["cases"].toArray();
        QCOMPARE(normals.size(), 20);
        QVERIFY(normals[0]["passed"].toBool());
        int failed = 0;
        for (const QJsonValue &c : normals)
            failed += !c["passed"].toBool();
        QVERIFY2(failed >= 10, qPrintable(QString::number(failed)));

        // The reflection's sign changes every highlight: most cases fail, with big differences.
        const QJsonArray reflect = gradeOne(kData + "/reflect_sign.frag")["cases"].toArray();
        int reflectFailed = 0, largest = 0;
        for (const QJsonValue &c : reflect) {
            reflectFailed += !c["passed"].toBool();
            largest = std::max(largest, c["largest"].toInt());
        }
        QVERIFY2(reflectFailed >= 10, qPrintable(QString::number(reflectFailed)));
        QVERIFY(largest > 50);
    }

    void theSameSeedGivesTheSameReport()
    {
        QStringList reports;
        for (const char *seed : {"7", "7", "8"}) {
            const QString report = m_dir.filePath(QString("seed%1.csv").arg(reports.size()));
            const Run r = run({"--grade", kData + "/reflect_sign.vert", kData + "/normal_matrix",
                               "--exercise", kExercise, "--seed", seed, "--report", report});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            QFile f(report);
            QVERIFY(f.open(QIODevice::ReadOnly));
            reports << QString::fromUtf8(f.readAll());
        }
        QCOMPARE(reports[0], reports[1]);
        QVERIFY(reports[0] != reports[2]); // other cases, other numbers
    }

    // A submission given as a scene file with a program is graded like a pair.
    void aSceneFileSubmission()
    {
        const QString scene = m_dir.filePath("carol.json");
        QFile vert(kData + "/correct/lighting.vert"), frag(kData + "/correct/lighting.frag");
        QVERIFY(vert.open(QIODevice::ReadOnly) && frag.open(QIODevice::ReadOnly));
        const QJsonObject json{{"format", "lightbench-scene"},
                               {"version", 3},
                               {"program", QJsonObject{{"name", "carol"},
                                                       {"vertex", QString(vert.readAll())},
                                                       {"fragment", QString(frag.readAll())}}}};
        QVERIFY(write(scene, QJsonDocument(json).toJson()));
        const QJsonObject o = gradeOne(scene);
        QCOMPARE(o["submission"].toString(), QString("carol"));
        QCOMPARE(o["status"].toString(), QString("graded"));
    }

    void badInputIsNamed_data()
    {
        QTest::addColumn<QString>("what");
        QTest::newRow("missing exercise") << "missing exercise";
        QTest::newRow("exercise without reference") << "no reference";
        QTest::newRow("not an exercise") << "not an exercise";
        QTest::newRow("empty submission folder") << "empty folder";
        QTest::newRow("unreadable submission") << "fifo";
    }

    void badInputIsNamed()
    {
        QFETCH(QString, what);
        QString exercise = kExercise;
        QStringList submissions{kData + "/correct"};
        QString named;
        if (what == "missing exercise") {
            exercise = m_dir.filePath("nowhere.json");
            named = "nowhere.json";
        } else if (what == "no reference") {
            exercise = m_dir.filePath("noref.json");
            QVERIFY(write(exercise, R"({"format": "lightbench-scene", "version": 3,
                                        "exercise": {"title": "Lighting"}})"));
            named = "no reference program";
        } else if (what == "not an exercise") {
            exercise = LB_EXAMPLES_DIR "/toon.json";
            named = "not an exercise";
        } else if (what == "empty folder") {
            QVERIFY(QDir(m_dir.path()).mkpath("dave"));
            submissions << m_dir.filePath("dave");
            named = "dave: a folder needs one NAME.vert and one NAME.frag";
        } else {
            QVERIFY(QFile::copy(kData + "/correct/lighting.vert", m_dir.filePath("erin.vert")));
            QCOMPARE(mkfifo(QFile::encodeName(m_dir.filePath("erin.frag")).constData(), 0600), 0);
            submissions << m_dir.filePath("erin.vert");
            named = "erin.frag: not a regular file";
        }
        const Run r =
            run(QStringList{"--grade"} + submissions + QStringList{"--exercise", exercise});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(named.toUtf8()), r.err.constData());
        QCOMPARE(r.err.count("lightbench: "), 1);
        // Where only a submission is bad, the others are still graded.
        if (submissions.size() > 1)
            QVERIFY2(r.out.startsWith("correct: passed 20/20"), r.out.constData());
    }
};

QTEST_MAIN(TestGrading)
#include "test_grading.moc"
