// The grading reports as pure functions (grading_formats.h), fed hand-made reports: each
// format in its published shape (required keys and types, counts, scores that are the sums of
// the passed cases' points), the known mistake's hint in every one, the seed and the version
// in every one, and names that try to break each shape. Bad input tried (as submission names
// and diagnostics): a double quote, "<script>" and "&amp;", a line break followed by a fake
// summary line, a BEL control character, a comma and a leading "=", non-ASCII ("Ünïcødé 名").
// Also what the cases are worth (exercise.h's "points", with a wrong-length list, negative,
// huge, NaN and text points) and the progress line's text.
#include "exercise.h"
#include "grading_formats.h"
#include "grading_progress.h"
#include "message_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>

using namespace lb;

namespace {

const QString kNasty =
    QString::fromUtf8("quo\"te <script>&amp;\nbob: passed, 20/20\x07,=Ünïcødé 名");
const QString kHint = "Multiply the normal by the normal matrix <mat3>, not by \"mModelView\".";

GradingRun sampleRun()
{
    GradingRun run;
    run.casePoints = {10, 20, 30, 40}; // 100 in all, unequal: a sum of the wrong cases shows
    run.seed = 7;
    run.version = "9.8.7";
    return run;
}

CaseResult caseResult(bool passed, int largest, double share)
{
    CaseResult c;
    c.passed = passed;
    c.largest = largest;
    c.shareWithin = share;
    c.compared = 5000;
    return c;
}

// Passes cases 0 and 2 (40 points of 100), with a known mistake's hint; nasty name.
GradedSubmission failing()
{
    GradedSubmission s;
    s.name = kNasty;
    s.seconds = 2.0;
    s.report.status = "graded";
    s.report.cases = {caseResult(true, 1, 1.0), caseResult(false, 104, 0.7),
                      caseResult(true, 2, 0.995), caseResult(false, 90, 0.5)};
    s.report.mistake = MistakeMatch{0, "normal matrix", kHint, 0.99};
    return s;
}

GradedSubmission passing()
{
    GradedSubmission s;
    s.name = "correct";
    s.seconds = 1.5;
    s.report.status = "graded";
    for (int k = 0; k < 4; ++k)
        s.report.cases.push_back(caseResult(true, 1, 1.0));
    return s;
}

GradedSubmission notCompiling()
{
    GradedSubmission s;
    s.name = "syntax <b>";
    s.seconds = 0.5;
    s.report.status = "does not compile";
    s.report.diagnostic =
        "syntax.frag:26: syntax error, unexpected '<' near \"<script>\"\nnext line";
    return s;
}

QJsonObject object(const QByteArray &bytes)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        qWarning("not a JSON object: %s", qPrintable(error.errorString()));
    return doc.object();
}

} // namespace

class TestGradingFormats : public QObject
{
    Q_OBJECT
private slots:
    void scoresArePassedPoints()
    {
        const GradingRun run = sampleRun();
        QCOMPARE(maxPoints(run), 100.0);
        QCOMPARE(score(run, failing().report), 40.0);
        QCOMPARE(score(run, passing().report), 100.0);
        QCOMPARE(score(run, notCompiling().report), 0.0);
        // Equal shares of 100 over 3 cases add up to 100 again, not 99.99999.
        GradingSpec spec;
        spec.cases = 3;
        GradingRun thirds;
        thirds.casePoints = pointsPerCase(spec);
        GradingReport all;
        all.status = "graded";
        all.cases.assign(3, caseResult(true, 0, 1.0));
        QCOMPARE(pointsText(score(thirds, all)), QString("100"));
        QCOMPARE(pointsText(maxPoints(thirds)), QString("100"));
    }

    void csvHasPointsHintSeedAndVersion()
    {
        const QByteArray bytes = csvReport(sampleRun(), {failing(), passing(), notCompiling()});
        const QList<QByteArray> lines = bytes.trimmed().split('\n');
        // The name's line break is an escape: one line per row.
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines[0], QByteArray("submission,status,cases_passed,cases,worst_difference,"
                                      "mean_share_within,first_diagnostic,points,max_points,"
                                      "hint,seed,lightbench"));
        QVERIFY2(lines[1].contains(",40,100,"), lines[1].constData());
        QVERIFY(lines[1].contains(escapedControls(kHint).toUtf8().replace('"', "\"\"")));
        QVERIFY(lines[1].endsWith(",7,9.8.7"));
        QVERIFY(lines[2].startsWith("correct,graded,4,4,") && lines[2].contains(",100,100,"));
        QVERIFY2(lines[3].contains("does not compile,,,,,") && lines[3].contains(",0,100,,7,"),
                 lines[3].constData());
        QVERIFY(!bytes.contains('\x07'));
    }

    void junitIsWellFormedWithTheRightCounts()
    {
        const QByteArray bytes = junitReport(sampleRun(), {failing(), passing(), notCompiling()});
        QXmlStreamReader xml(bytes);
        int suites = 0, cases = 0, failuresSeen = 0, errorsSeen = 0;
        QMap<QString, QString> properties;
        QXmlStreamAttributes top;
        QStringList suiteNames, failureTexts;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement)
                continue;
            const QXmlStreamAttributes a = xml.attributes();
            if (xml.name() == u"testsuites") {
                top = a;
            } else if (xml.name() == u"testsuite") {
                ++suites;
                suiteNames << a.value("name").toString();
            } else if (xml.name() == u"testcase") {
                ++cases;
                QVERIFY(!a.value("classname").isEmpty() && !a.value("time").isEmpty());
            } else if (xml.name() == u"failure") {
                ++failuresSeen;
                failureTexts << a.value("message").toString();
            } else if (xml.name() == u"error") {
                ++errorsSeen;
                QCOMPARE(a.value("message").toString(), QString("does not compile"));
                QVERIFY(xml.readElementText().contains("unexpected '<' near \"<script>\"\n"));
            } else if (xml.name() == u"property") {
                properties[a.value("name").toString()] = a.value("value").toString();
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(suites, 3);
        QCOMPARE(cases, 4 + 4 + 1);
        QCOMPARE(failuresSeen, 2);
        QCOMPARE(errorsSeen, 1);
        QCOMPARE(top.value("tests").toInt(), cases);
        QCOMPARE(top.value("failures").toInt(), failuresSeen);
        QCOMPARE(top.value("errors").toInt(), errorsSeen);
        QCOMPARE(suiteNames[0], escapedName(kNasty)); // escaped as the summary line shows it
        QVERIFY(failureTexts.join('|').contains(kHint));
        QCOMPARE(properties["seed"], QString("7"));
        QCOMPARE(properties["lightbench"], QString("9.8.7"));
    }

    void githubClassroomResult()
    {
        const QJsonObject fail = object(githubResult(sampleRun(), {failing()}));
        QCOMPARE(fail["version"].toInt(), 1);
        QCOMPARE(fail["status"].toString(), QString("fail"));
        QCOMPARE(fail["max_score"].toDouble(), 100.0);
        QCOMPARE(fail["seed"].toInt(), 7);
        QCOMPARE(fail["lightbench"].toString(), QString("9.8.7"));
        const QJsonArray tests = fail["tests"].toArray();
        QCOMPARE(tests.size(), 4);
        double sum = 0;
        for (const QJsonValue &v : tests) {
            const QJsonObject t = v.toObject();
            for (const char *key : {"name", "status", "message", "test_code"})
                QVERIFY2(t[key].isString(), key);
            QVERIFY(!t.contains("execution_time")); // the same bytes on a busy machine
            QVERIFY(t["score"].isDouble() && t["line_no"].isDouble());
            QCOMPARE(t["line_no"].toInt(), 0); // the reporter prints "- line N" unless 0
            QVERIFY(t["status"] == "pass" || t["status"] == "fail");
            QVERIFY(t["test_code"].toString().contains("seed 7"));
            sum += t["score"].toDouble();
            if (t["status"] == "fail") { // the reporter prints test_code, not the message
                QVERIFY(t["message"].toString().contains(kHint));
                QVERIFY(t["test_code"].toString().contains(kHint));
            }
        }
        QCOMPARE(sum, 40.0);
        // Equal shares that are no binary fractions (100/6, 100/7, ...): the scores, added in
        // order as the reporter adds them, are exactly full marks when every case passed, and
        // never more than max_score otherwise.
        for (int cases : {6, 7, 9, 11, 12, 14, 17, 21, 30}) {
            GradingSpec spec;
            spec.cases = cases;
            GradingRun run;
            run.casePoints = pointsPerCase(spec);
            for (int passed : {cases, cases - 1, cases / 2}) {
                GradedSubmission s = passing();
                s.report.cases.assign(std::size_t(cases), caseResult(false, 9, 0.5));
                for (int k = 0; k < passed; ++k)
                    s.report.cases[std::size_t(k)] = caseResult(true, 0, 1.0);
                const QJsonObject result = object(githubResult(run, {s}));
                double total = 0.0;
                for (const QJsonValue &t : result["tests"].toArray()) {
                    QVERIFY(t["score"].toDouble() >= 0.0);
                    total += t["score"].toDouble();
                }
                const QString where = QString("%1 of %2 cases").arg(passed).arg(cases);
                if (passed == cases)
                    QVERIFY2(total == 100.0, qPrintable(where));
                QVERIFY2(total <= 100.0, qPrintable(where));
                QVERIFY2(std::abs(total - score(run, s.report)) <= 1.0 / 64, qPrintable(where));
            }
        }
        // Unequal points with cases worth 0 or less than 1/64 (a reviewer's lists): no case
        // below 0, never more than max_score, within 1/64 of the score.
        const std::vector<std::pair<std::vector<double>, std::vector<bool>>> lists{
            {{16.67, 16.67, 16.67, 16.67, 16.67, 16.67, 0}, {1, 1, 1, 1, 1, 0, 1}},
            {{50.005, 50.005, 0}, {1, 1, 0}},
            {{0.007, 0.007, 0.007, 0, 0.5}, {0, 0, 0, 1, 1}},
            {{0.007, 0.007, 0.007, 0, 0.5}, {1, 1, 1, 1, 0}}};
        for (const auto &[points, passed] : lists) {
            GradingRun run;
            run.casePoints = points;
            GradedSubmission s = passing();
            s.report.cases.clear();
            for (bool p : passed)
                s.report.cases.push_back(caseResult(p, p ? 0 : 9, p ? 1.0 : 0.5));
            double total = 0.0;
            for (const QJsonValue &t : object(githubResult(run, {s}))["tests"].toArray()) {
                QVERIFY(t["score"].toDouble() >= 0.0);
                total += t["score"].toDouble();
            }
            QVERIFY(total <= maxPoints(run));
            QVERIFY(std::abs(total - score(run, s.report)) <= 1.0 / 64);
        }
        QCOMPARE(object(githubResult(sampleRun(), {passing()}))["status"].toString(),
                 QString("pass"));
        const QJsonObject error = object(githubResult(sampleRun(), {notCompiling()}));
        QCOMPARE(error["status"].toString(), QString("error"));
        QCOMPARE(error["tests"].toArray().size(), 1);
        QCOMPARE(error["tests"][0]["score"].toDouble(), 0.0);
        QVERIFY(error["tests"][0]["message"].toString().startsWith("does not compile: syntax"));
    }

    void gradescopeResults()
    {
        for (const GradedSubmission &row : {failing(), passing(), notCompiling()}) {
            const QJsonObject r = object(lb::gradescopeResults(sampleRun(), {row}));
            QVERIFY(r["score"].isDouble() && !r.contains("execution_time"));
            QVERIFY(r["output"].toString().contains("lightbench 9.8.7 with seed 7"));
            QCOMPARE(r["visibility"].toString(), QString("visible"));
            QVERIFY(r["stdout_visibility"].isString());
            QCOMPARE(r["extra_data"]["seed"].toInt(), 7);
            double sum = 0, most = 0;
            for (const QJsonValue &v : r["tests"].toArray()) {
                const QJsonObject t = v.toObject();
                for (const char *key : {"name", "number", "output", "visibility", "status"})
                    QVERIFY2(t[key].isString(), key);
                QVERIFY(t["status"] == "passed" || t["status"] == "failed");
                QVERIFY(t["score"].isDouble() && t["max_score"].isDouble());
                sum += t["score"].toDouble();
                most += t["max_score"].toDouble();
            }
            QCOMPARE(r["score"].toDouble(), sum);
            QCOMPARE(r["score"].toDouble(), score(sampleRun(), row.report));
            QCOMPARE(most, 100.0);
        }
        const QJsonObject f = object(lb::gradescopeResults(sampleRun(), {failing()}));
        QVERIFY(f["output"].toString().contains(kHint));
        QVERIFY(!f["output"].toString().contains('\x07'));
        QCOMPARE(f["output"].toString().count('\n'), 1); // the summary, then "Graded by"
    }

    void codeRunnerOutcome()
    {
        const QJsonObject f = object(lb::codeRunnerOutcome(sampleRun(), {failing()}));
        QCOMPARE(f["fraction"].toDouble(), 0.4);
        const QString prologue = f["prologuehtml"].toString();
        // Student text is escaped: their "<script>" stays text.
        QVERIFY2(!prologue.contains("<script>") && prologue.contains("&lt;script&gt;&amp;amp;"),
                 qPrintable(prologue));
        QVERIFY(prologue.contains(kHint.toHtmlEscaped()));
        QVERIFY(f["epiloguehtml"].toString().contains("lightbench 9.8.7 with seed 7"));
        const QJsonArray table = f["testresults"].toArray();
        QCOMPARE(table.size(), 1 + 4);
        QCOMPARE(table[0][0].toString(), QString("iscorrect"));
        int correct = 0;
        for (int i = 1; i < table.size(); ++i) {
            QCOMPARE(table[i].toArray().size(), table[0].toArray().size());
            correct += table[i][0].toInt();
        }
        QCOMPARE(correct, 2);
        QCOMPARE(object(lb::codeRunnerOutcome(sampleRun(), {passing()}))["fraction"].toDouble(),
                 1.0);
        const QJsonObject n = object(lb::codeRunnerOutcome(sampleRun(), {notCompiling()}));
        QCOMPARE(n["fraction"].toDouble(), 0.0);
        QVERIFY(n["prologuehtml"].toString().contains("&quot;&lt;script&gt;&quot;"));
        // A batch error (a faulty exercise) is said in the JSON, not on stderr.
        GradingRun broken = sampleRun();
        broken.error = "--exercise: x.json: reference does not build";
        const QJsonObject e = object(lb::codeRunnerOutcome(broken, {}));
        QCOMPARE(e["fraction"].toDouble(), 0.0);
        QVERIFY(e["prologuehtml"].toString().contains("reference does not build"));
    }

    void everyFormatSaysTheHint()
    {
        for (int f = 0; f < reportFormatNames().size(); ++f) {
            const QByteArray bytes = reportBytes(ReportFormat(f), sampleRun(), {failing()});
            const QByteArray hint = escapedControls(kHint).toUtf8();
            // As each format escapes it: CSV doubles quotes, XML and HTML use entities, JSON
            // backslashes quotes.
            QVERIFY2(bytes.contains(hint) ||
                         bytes.contains(QByteArray(hint).replace('"', "\"\"")) ||
                         bytes.contains(QString(kHint).toHtmlEscaped().toUtf8()) ||
                         bytes.contains(QByteArray(hint).replace('"', "\\\"")) ||
                         bytes.contains(QByteArray(hint)
                                            .replace('"', "&quot;")
                                            .replace('<', "&lt;")
                                            .replace('>', "&gt;")),
                     qPrintable(reportFormatNames()[f]));
        }
        QVERIFY(summaryLine(sampleRun(), failing()).contains("hint: " + kHint));
        QVERIFY(!summaryLine(sampleRun(), failing()).contains('\n'));
    }

    void formatWords()
    {
        QCOMPARE(reportFormatNames(),
                 QStringList({"csv", "junit", "gradescope", "github", "coderunner"}));
        QCOMPARE(parseReportFormat("junit"), std::optional<ReportFormat>(ReportFormat::JUnit));
        QVERIFY(!parseReportFormat("JUnit") && !parseReportFormat("xml"));
        QVERIFY(!describesOneSubmission(ReportFormat::Csv));
        QVERIFY(describesOneSubmission(ReportFormat::CodeRunner));
    }

    void pointsOfAnExercise_data()
    {
        QTest::addColumn<QJsonValue>("points");
        QTest::addColumn<bool>("usable");
        QTest::newRow("a total") << QJsonValue(60) << true;
        QTest::newRow("one per case") << QJsonValue(QJsonArray{1, 2, 3, 4}) << true;
        QTest::newRow("a list too short") << QJsonValue(QJsonArray{1, 2, 3}) << false;
        QTest::newRow("a list too long") << QJsonValue(QJsonArray{1, 2, 3, 4, 5}) << false;
        QTest::newRow("negative") << QJsonValue(-1) << false;
        QTest::newRow("negative in the list") << QJsonValue(QJsonArray{1, -2, 3, 4}) << false;
        QTest::newRow("huge") << QJsonValue(1e300) << false;
        QTest::newRow("NaN") << QJsonValue(std::nan("")) << false;
        QTest::newRow("text") << QJsonValue("100") << false;
        QTest::newRow("text in the list") << QJsonValue(QJsonArray{1, "2", 3, 4}) << false;
    }

    void pointsOfAnExercise()
    {
        QFETCH(QJsonValue, points);
        QFETCH(bool, usable);
        Exercise e;
        e.reference.vertex = "void main() {}";
        e.reference.fragment = "void main() {}";
        e.grading.cases = 4;
        QJsonObject json = exerciseJson(e);
        QCOMPARE(json["grading"].toObject()["points"].toDouble(),
                 100.0); // written back, the default
        QJsonObject grading = json["grading"].toObject();
        grading["points"] = points;
        json["grading"] = grading;
        QStringList ignored;
        const ExerciseRead read = readExercise(json, &ignored);
        QVERIFY(read.exercise);
        const std::vector<double> each = pointsPerCase(read.exercise->grading);
        QCOMPARE(each.size(), std::size_t(4));
        if (usable) {
            QVERIFY2(ignored.isEmpty(), qPrintable(ignored.join('|')));
            // Read back as written.
            QCOMPARE(exerciseJson(*read.exercise)["grading"].toObject()["points"], points);
        } else {
            QCOMPARE(ignored.size(), 1);
            QVERIFY2(ignored[0].startsWith("exercise.grading.points ("), qPrintable(ignored[0]));
            QCOMPARE(each, std::vector<double>(4, 25.0)); // the default: 100 in equal shares
        }
    }

    void aMisspeltGradingFieldIsNamed()
    {
        Exercise e;
        e.reference.vertex = e.reference.fragment = "void main() {}";
        QJsonObject json = exerciseJson(e);
        QJsonObject grading = json["grading"].toObject();
        grading["pionts"] = 50;
        json["grading"] = grading;
        QStringList ignored;
        readExercise(json, &ignored);
        QCOMPARE(ignored, QStringList{"exercise.grading.pionts (unknown field)"});
    }

    void progressText()
    {
        QCOMPARE(lb::progressText(0, 30, 0), QString("graded 0/30, 0:00 elapsed"));
        QCOMPARE(lb::progressText(3, 30, 12000),
                 QString("graded 3/30, 0:12 elapsed, about 1:48 left"));
        QCOMPARE(lb::progressText(30, 30, 125000), QString("graded 30/30, 2:05 elapsed"));
        QCOMPARE(lb::progressText(1, 3, 3723000),
                 QString("graded 1/3, 1:02:03 elapsed, about 2:04:06 left"));
    }
};

QTEST_GUILESS_MAIN(TestGradingFormats)
#include "test_grading_formats.moc"
