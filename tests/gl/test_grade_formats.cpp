// --report-format (issue 33) from the sample submissions in tests/data/grading, as the
// platforms read each file: the class as CSV and as JUnit XML (one run each: counts, points,
// seed and version), and one submission (the correct one, a failing one, one that does not
// compile) as GitHub Classroom's result (exit 3 unless every case passed), Gradescope's
// results.json and CodeRunner's combinator JSON on standard output (nothing on stderr, even
// for a faulty exercise). The sheet folder holds only the last run's sheets, and strangers'
// files stay. No progress line without a terminal.
// Bad input tried: an unknown format word, a format without --report, github with two
// submissions, coderunner with a missing exercise and with two submissions, an exercise whose
// points list is one short or negative, a sheet list naming "../outside.png", a text file and
// a symbolic link.
#include "platform_skips.h"
#include "program_run.h"

#include "csv_rows.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace {

const QString kData = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");
const QString kVersion = QStringLiteral(LB_PROJECT_VERSION);

using Run = ProgramRun;

Run run(const QStringList &args)
{
    return runProgram(LIGHTBENCH_EXE, args, 300000);
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QJsonObject object(const QByteArray &bytes)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        qWarning("not JSON: %s in %s", qPrintable(error.errorString()), bytes.left(300).data());
    return doc.object();
}

// The sample exercise with its grading section changed, as DIR/FILE.
QString exerciseWith(const QDir &dir, const QString &file, const QString &key,
                     const QJsonValue &value)
{
    QFile in(kExercise);
    if (!in.open(QIODevice::ReadOnly))
        return {};
    QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
    QJsonObject exercise = root["exercise"].toObject();
    QJsonObject grading = exercise["grading"].toObject();
    grading[key] = value;
    exercise["grading"] = grading;
    root["exercise"] = exercise;
    const QString path = dir.filePath(file);
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(QJsonDocument(root).toJson()) <= 0)
        return {};
    return path;
}

const QStringList kClass{kData + "/correct", kData + "/reflect_sign.vert",
                         kData + "/normal_matrix.frag", kData + "/syntax", kData + "/loop.vert"};

} // namespace

class TestGradeFormats : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private slots:
    void theClassAsCsv()
    {
        const QString report = m_dir.filePath("class.csv");
        const Run r = run(QStringList{"--grade"} + kClass +
                          QStringList{"--exercise", kExercise, "--report", report,
                                      "--report-format", "csv", "--seed", "3"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(!r.err.contains("graded "), r.err.constData()); // no terminal: no progress
        const QList<QStringList> rows = csvRows(report);
        QCOMPARE(rows.size(), 6);
        const QStringList &header = rows[0];
        QCOMPARE(header.size(), 12);
        const int passedAt = header.indexOf("cases_passed"), pointsAt = header.indexOf("points");
        const int hintAt = header.indexOf("hint");
        for (int i = 1; i < rows.size(); ++i) {
            QCOMPARE(rows[i].size(), 12);
            QCOMPARE(rows[i].last(), kVersion);
            QCOMPARE(rows[i][rows[i].size() - 2], QString("3"));
            QCOMPARE(rows[i][rows[i].size() - 4], QString("100")); // max_points
        }
        // 20 cases, 5 points each: the points are the passed cases'.
        const QStringList &correct = rows[1], &reflect = rows[2];
        QCOMPARE(correct[pointsAt], QString("100"));
        QCOMPARE(reflect[pointsAt].toDouble(), 5.0 * reflect[passedAt].toInt());
        // The known mistake's hint, for the failing submission only (a hint may hold commas).
        QCOMPARE(correct[hintAt], QString());
        QVERIFY2(reflect[hintAt].contains("reflect"), qPrintable(reflect[hintAt]));
        const QList<QByteArray> lines = readAll(report).trimmed().split('\n');
        QVERIFY(lines[4].startsWith("syntax,does not compile,"));
        QVERIFY2(r.out.split('\n')[0].startsWith("correct: passed, 20/20 cases passed (100/100 "
                                                 "points)"),
                 r.out.constData());
    }

    void theClassAsJUnit()
    {
        const QString report = m_dir.filePath("class.xml");
        const Run r = run(
            QStringList{"--grade"} + kClass +
            QStringList{"--exercise", kExercise, "--report", report, "--report-format", "junit"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QXmlStreamReader xml(readAll(report));
        QXmlStreamAttributes top;
        QMap<QString, QXmlStreamAttributes> suites;
        QMap<QString, int> casesOf, failuresOf, errorsOf;
        QString suite;
        QStringList seeds, versions;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement)
                continue;
            const QXmlStreamAttributes a = xml.attributes();
            if (xml.name() == u"testsuites")
                top = a;
            else if (xml.name() == u"testsuite")
                suites[suite = a.value("name").toString()] = a;
            else if (xml.name() == u"testcase")
                ++casesOf[suite];
            else if (xml.name() == u"failure")
                ++failuresOf[suite];
            else if (xml.name() == u"error")
                ++errorsOf[suite];
            else if (xml.name() == u"property" && a.value("name") == u"seed")
                seeds << a.value("value").toString();
            else if (xml.name() == u"property" && a.value("name") == u"lightbench")
                versions << a.value("value").toString();
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(suites.keys(),
                 QStringList({"correct", "loop", "normal_matrix", "reflect_sign", "syntax"}));
        int tests = 0, failures = 0, errors = 0;
        for (const QString &name : suites.keys()) {
            QCOMPARE(suites[name].value("tests").toInt(), casesOf[name]);
            QCOMPARE(suites[name].value("failures").toInt(), failuresOf[name]);
            QCOMPARE(suites[name].value("errors").toInt(), errorsOf[name]);
            tests += casesOf[name];
            failures += failuresOf[name];
            errors += errorsOf[name];
        }
        QCOMPARE(casesOf["correct"], 20);
        QCOMPARE(failuresOf["correct"], 0);
        QVERIFY(failuresOf["reflect_sign"] > 0 && failuresOf["normal_matrix"] > 0);
        QCOMPARE(errorsOf["syntax"], 1);
        QCOMPARE(errorsOf["loop"], 1);
        QCOMPARE(top.value("tests").toInt(), tests);
        QCOMPARE(top.value("failures").toInt(), failures);
        QCOMPARE(top.value("errors").toInt(), errors);
        QCOMPARE(seeds, QStringList(5, "1"));
        QCOMPARE(versions, QStringList(5, kVersion));
    }

    void oneSubmissionFormats_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("submission");
        QTest::addColumn<int>("exitCode");
        for (const char *format : {"github", "gradescope", "coderunner"})
            for (const auto &[submission, github] :
                 {std::pair<const char *, int>{"correct", 0}, {"reflect_sign", 3}, {"syntax", 3}})
                QTest::newRow(qPrintable(QString("%1 %2").arg(format, submission)))
                    << format << submission << (QString(format) == "github" ? github : 0);
    }

    void oneSubmissionFormats()
    {
        QFETCH(QString, format);
        QFETCH(QString, submission);
        QFETCH(int, exitCode);
        // CodeRunner reads standard output; the others a file.
        const bool toStdout = format == "coderunner";
        const QString report = toStdout ? "-" : m_dir.filePath(format + submission + ".json");
        const Run r =
            run({"--grade", kData + "/" + submission + (submission == "correct" ? "" : ".vert"),
                 "--exercise", kExercise, "--report", report, "--report-format", format});
        QVERIFY2(r.exitCode == exitCode, r.err.constData());
        const QJsonObject o = object(toStdout ? r.out : readAll(report));
        QVERIFY(!o.isEmpty());
        const bool correct = submission == "correct", graded = submission != "syntax";
        if (format == "coderunner") {
            QCOMPARE(r.err, QByteArray()); // nothing on stderr: not even the summary line
            QVERIFY(o["fraction"].isDouble() && o["prologuehtml"].isString());
            QCOMPARE(o["fraction"].toDouble() == 1.0, correct);
            QCOMPARE(o.contains("testresults"), graded);
            const QJsonArray table = o["testresults"].toArray();
            int ticks = 0;
            for (int i = 1; i < table.size(); ++i)
                ticks += table[i][0].toInt();
            if (graded) {
                QCOMPARE(table.size(), 21);
                QCOMPARE(table[0][0].toString(), QString("iscorrect"));
                QCOMPARE(o["fraction"].toDouble(), ticks / 20.0);
            } else {
                QVERIFY(o["prologuehtml"].toString().contains("does not compile"));
            }
            QVERIFY(o["epiloguehtml"].toString().contains(kVersion));
            return;
        }
        double sum = 0, most = 0;
        for (const QJsonValue &v : o["tests"].toArray()) {
            QVERIFY(v["score"].isDouble() && v["name"].isString());
            sum += v["score"].toDouble();
            most += format == "gradescope" ? v["max_score"].toDouble() : 0;
        }
        if (format == "github") {
            QCOMPARE(o["version"].toInt(), 1);
            QCOMPARE(o["max_score"].toDouble(), 100.0);
            QCOMPARE(o["status"].toString(), QString(correct ? "pass" : graded ? "fail" : "error"));
            QCOMPARE(o["tests"].toArray().size(), graded ? 20 : 1);
            QCOMPARE(o["lightbench"].toString(), kVersion);
            QCOMPARE(sum == 100.0, correct);
        } else {
            QCOMPARE(o["score"].toDouble(), sum);
            QCOMPARE(most, 100.0);
            QCOMPARE(o["score"].toDouble() == 100.0, correct);
            QVERIFY(!o.contains("execution_time") && o["output"].isString());
            QVERIFY(o["output"].toString().contains("lightbench " + kVersion + " with seed 1"));
            QCOMPARE(o["tests"].toArray().size(), graded ? 20 : 1);
        }
        QVERIFY(!r.out.isEmpty()); // the summary line, on stdout beside a report file
    }

    // CodeRunner shows any stderr as the grader's failure: a batch error is said in the JSON.
    void codeRunnerSaysBatchErrorsInItsJson_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        QTest::newRow("no exercise")
            << QStringList{kData + "/correct", "--exercise", "/nonexistent/exercise.json"}
            << "exercise.json";
        QTest::newRow("two submissions")
            << QStringList{kData + "/correct", kData + "/syntax", "--exercise", kExercise}
            << "describes one submission";
    }

    void codeRunnerSaysBatchErrorsInItsJson()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        const Run r = run(QStringList{"--grade"} + args +
                          QStringList{"--report", "-", "--report-format", "coderunner"});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QByteArray());
        const QJsonObject o = object(r.out);
        QCOMPARE(o["fraction"].toDouble(-1), 0.0);
        QVERIFY2(o["prologuehtml"].toString().contains(said), r.out.constData());
    }

    void badInputIsNamed_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        const QString csv = m_dir.filePath("bad.csv");
        QTest::newRow("an unknown format")
            << QStringList{kData + "/correct", "--exercise", kExercise, "--report", csv,
                           "--report-format",  "xml"}
            << "--report-format: unknown value 'xml' (expected "
               "csv|junit|gradescope|github|coderunner)";
        QTest::newRow("a format without --report")
            << QStringList{kData + "/correct", "--exercise", kExercise, "--report-format", "junit"}
            << "--report-format: goes with --report";
        QTest::newRow("github with two submissions")
            << QStringList{kData + "/correct",
                           kData + "/syntax.vert",
                           kData + "/syntax.frag",
                           kData + "/loop",
                           "--exercise",
                           kExercise,
                           "--report",
                           csv,
                           "--report-format",
                           "github"}
            << "--report-format github: describes one submission (the platform grades one "
               "student per run); 3 were given";
        QTest::newRow("points one short")
            << QStringList{kData + "/correct", "--exercise",
                           exerciseWith(QDir(m_dir.path()), "short.json", "points",
                                        QJsonArray{5, 5, 5})}
            << "exercise.grading.points (3 values for 20 cases (one per case))";
        QTest::newRow("negative points")
            << QStringList{kData + "/correct", "--exercise",
                           exerciseWith(QDir(m_dir.path()), "negative.json", "points", -100)}
            << "exercise.grading.points (not a number of points from 0 to 1000000";
        // Issue 49: an empty --sheets wrote nothing and said nothing; /proc passed the check
        // (root may write there) and then failed every sheet.
        QTest::newRow("an empty --sheets")
            << QStringList{kData + "/correct", "--exercise", kExercise, "--sheets", ""}
            << "--sheets: needs a folder";
        QTest::newRow("--sheets /proc")
            << QStringList{kData + "/correct", "--exercise", kExercise, "--sheets", "/proc"}
            << "--sheets: /proc/.lightbench-sheets: cannot write in /proc:";
    }

    void badInputIsNamed()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        const Run r = run(QStringList{"--grade"} + args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
        QCOMPARE(r.err.trimmed().count('\n'), 0); // one line
        QCOMPARE(r.out, QByteArray());            // nobody graded
    }

    // A sheet folder holds only this run's sheets: the last run's go, strangers' stay.
    void sheetsOfTheLastRunGo()
    {
        const QDir sheets(m_dir.filePath("sheets"));
        const Run first = run(
            {"--grade", kData + "/correct", "--exercise", kExercise, "--sheets", sheets.path()});
        QVERIFY2(first.exitCode == 0, first.err.constData());
        QVERIFY(sheets.exists("correct.png"));
        QFile stranger(sheets.filePath("stranger.png")), notes(sheets.filePath("notes.txt"));
        QVERIFY(stranger.open(QIODevice::WriteOnly) && notes.open(QIODevice::WriteOnly));
        stranger.close();
        notes.close();
        const Run second = run({"--grade", kData + "/reflect_sign.vert", "--exercise", kExercise,
                                "--sheets", sheets.path()});
        QVERIFY2(second.exitCode == 0, second.err.constData());
        QVERIFY(!sheets.exists("correct.png"));
        QVERIFY(sheets.exists("reflect_sign.png"));
        QVERIFY(sheets.exists("stranger.png") && sheets.exists("notes.txt"));

        // A run that ends in the exercise's fault (its reference does not build, found by the
        // first child) grades nobody and removes nothing: the last run's sheet stays.
        const QString broken = m_dir.filePath("broken_reference.json");
        {
            QFile in(kExercise), out(broken);
            QVERIFY(in.open(QIODevice::ReadOnly) && out.open(QIODevice::WriteOnly));
            QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
            QJsonObject exercise = root["exercise"].toObject();
            exercise["reference"] =
                QJsonObject{{"vertex", "void main() { gl_Position = vec4(0.0); }"},
                            {"fragment", "void main() { this does not compile }"}};
            root["exercise"] = exercise;
            out.write(QJsonDocument(root).toJson());
        }
        const Run faulty =
            run({"--grade", kData + "/correct", "--exercise", broken, "--sheets", sheets.path()});
        QCOMPARE(faulty.exitCode, 2);
        QVERIFY(sheets.exists("reflect_sign.png"));
        QVERIFY(!sheets.exists("correct.png"));

        // The same student again, but not graded this time (it does not compile): last run's
        // sheet of theirs goes too, since this run has none for them.
        const QDir again(m_dir.filePath("again/reflect_sign"));
        QVERIFY(again.mkpath("."));
        QVERIFY(QFile::copy(kData + "/syntax.vert", again.filePath("lighting.vert")));
        QVERIFY(QFile::copy(kData + "/syntax.frag", again.filePath("lighting.frag")));
        const Run notGraded =
            run({"--grade", again.path(), "--exercise", kExercise, "--sheets", sheets.path()});
        QVERIFY2(notGraded.out.contains("reflect_sign: does not compile"), notGraded.out);
        QVERIFY(!sheets.exists("reflect_sign.png"));
        QVERIFY(sheets.exists("stranger.png") && sheets.exists("notes.txt"));

        // A list that names what the batch did not write removes nothing of it.
        QFile outside(m_dir.filePath("outside.png"));
        QVERIFY(outside.open(QIODevice::WriteOnly));
        outside.close();
        QVERIFY(QFile::link(sheets.filePath("stranger.png"), sheets.filePath("link.png")));
        QFile list(sheets.filePath(".lightbench-sheets"));
        QVERIFY(list.open(QIODevice::WriteOnly));
        list.write(R"({"sheets": ["../outside.png", "notes.txt", "link.png", 5]})");
        list.close();
        const Run third = run({"--grade", kData + "/reflect_sign.vert", "--exercise", kExercise,
                               "--sheets", sheets.path()});
        QVERIFY2(third.exitCode == 0, third.err.constData());
        QVERIFY(QFile::exists(m_dir.filePath("outside.png")));
        QVERIFY(sheets.exists("notes.txt") && sheets.exists("stranger.png"));
        QVERIFY(QFileInfo(sheets.filePath("link.png")).isSymLink());
    }

    // A student graded as Correct, then as correct: on a file system that tells the two
    // apart, last run's Correct.png is cleaned up like any other stale sheet (it stayed for
    // ever, the list having dropped it); where the names are one file, it is kept.
    void sheetsDifferingByCaseAreCleanedUp()
    {
        const QDir sheets(m_dir.filePath("case-sheets"));
        const QDir upper(m_dir.filePath("case/Correct"));
        QVERIFY(upper.mkpath("."));
        for (const char *f : {"lighting.vert", "lighting.frag"})
            QVERIFY(QFile::copy(kData + "/correct/" + f, upper.filePath(f)));
        Run r = run({"--grade", upper.path(), "--exercise", kExercise, "--sheets", sheets.path()});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(sheets.exists("Correct.png"));
        r = run(
            {"--grade", kData + "/correct", "--exercise", kExercise, "--sheets", sheets.path()});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(sheets.exists("correct.png"));
        QVERIFY(!QDir(sheets.path()).entryList(QDir::Files).contains("Correct.png"));
    }

    // --report -: the report alone on standard output, the summary lines on stderr.
    void aReportOnStandardOutput()
    {
        const Run r = run({"--grade", kData + "/correct", kData + "/syntax", "--exercise",
                           kExercise, "--report", "-"});
        QCOMPARE(r.exitCode, 0);
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QVERIFY(lines[0].startsWith("submission,status,"));
        QVERIFY(lines[1].startsWith("correct,graded,20,20,"));
        QVERIFY2(r.err.contains("correct: passed, 20/20") && r.err.contains("syntax: does not"),
                 r.err.constData());
    }

    // A scene submitted whose program is over 1 MiB: refused with that reason (it was "the
    // scene file has no program").
    void aSceneWithAProgramTooLongSaysSo()
    {
        QJsonObject scene{
            {"format", "lightbench-scene"},
            {"version", 1},
            {"program", QJsonObject{{"vertex", QString(1100000, ' ') + "void main() {}"},
                                    {"fragment", "void main() {}"}}}};
        const QString path = m_dir.filePath("big.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(scene).toJson());
        f.close();
        const Run r = run({"--grade", path, "--exercise", kExercise});
        QVERIFY2(r.err.contains("the scene file's program cannot be used: program (the vertex "
                                "shader has 1100014 characters"),
                 r.err.constData());
    }

    // A report asked for on a stdout that was closed (`>&-`: descriptor 1 would be the X
    // server's socket, and the batch hung writing into it) or that is full (/dev/full): an
    // error with the reason, not exit 0 with the report lost.
    void aReportOnAClosedOrFullStandardOutputFails_data()
    {
        QTest::addColumn<QString>("redirect");
        QTest::addColumn<QString>("said");
        QTest::newRow("closed") << ">&-"
                                << "standard output is closed";
        QTest::newRow("full") << ">/dev/full"
                              << "could not write to standard output";
    }

    void aReportOnAClosedOrFullStandardOutputFails()
    {
        QFETCH(QString, redirect);
        QFETCH(QString, said);
        if (redirect == ">&-")
            LB_SKIP_WITHOUT_STANDARD_STREAMS();
        const Run r = runProgram("/bin/sh",
                                 {"-c", "exec \"$0\" \"$@\" " + redirect, LIGHTBENCH_EXE, "--grade",
                                  kData + "/correct", "--exercise", kExercise, "--report", "-"},
                                 300000);
        QVERIFY2(r.exitCode != 0, r.err.constData());
        QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestGradeFormats)
#include "test_grade_formats.moc"
