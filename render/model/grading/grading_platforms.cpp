// The result files of the platforms that grade one student per run: GitHub Classroom,
// Gradescope, Moodle CodeRunner (grading_formats.h says each shape and where it comes from).
#include "grading_formats.h"

#include "message_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

QString hintText(const GradingReport &report)
{
    return report.mistake ? escapedControls(report.mistake->hint.simplified()) : QString();
}

QString gradedBy(const GradingRun &run)
{
    return QString("Graded by lightbench %1 with seed %2.").arg(run.version).arg(run.seed);
}

// "does not compile: syntax.frag:26: ..." for a submission that was not graded.
QString notGradedText(const GradingReport &report)
{
    const QString diagnostic = escapedLines(report.diagnostic);
    return diagnostic.isEmpty() ? report.status : report.status + ": " + diagnostic;
}

// Why nobody was graded: the batch's error, or (a report written before the first submission
// finished, left by a batch that was stopped) that it was not.
QString batchErrorText(const GradingRun &run)
{
    return run.error.isEmpty() ? QString("not graded: the batch ended before it finished")
                               : escapedLines(run.error);
}

QByteArray json(const QJsonObject &object)
{
    return QJsonDocument(object).toJson(QJsonDocument::Indented);
}

// GitHub's reporter adds the tests' scores in floating point for the grade it sends: 100/6
// per case would add up to 100.00000000000001 or 99.99999999999999. Each passed case gets its
// points rounded down to 64ths of a point (exact in binary, so their sum is exact), and the
// passed case worth most gets what is left up to the score (itself rounded down to 64ths, and
// never above max_score): no case below 0, the sum the score to 1/64 of a point, full marks
// exactly max_score.
std::vector<double> githubCaseScores(const GradingRun &run, const GradingReport &r)
{
    std::vector<double> scores(r.cases.size(), 0.0);
    const auto down64ths = [](double points) { return std::floor(points * 64.0) / 64.0; };
    const bool allPassed = r.passedCount() == int(r.cases.size());
    const double target =
        allPassed ? maxPoints(run) : std::min(down64ths(score(run, r)), down64ths(maxPoints(run)));
    double given = 0.0;
    int most = -1;
    for (int k = 0; k < int(r.cases.size()); ++k)
        if (r.cases[std::size_t(k)].passed) {
            scores[std::size_t(k)] = down64ths(pointsOfCase(run, k));
            given += scores[std::size_t(k)];
            if (most < 0 || pointsOfCase(run, k) > pointsOfCase(run, most))
                most = k;
        }
    if (most >= 0)
        scores[std::size_t(most)] += std::max(0.0, target - given);
    return scores;
}

} // namespace

QByteArray githubResult(const GradingRun &run, const std::vector<GradedSubmission> &rows)
{
    // The reporter prints "name - line N" unless line_no is 0, and test_code under each test;
    // it sums the tests' scores against max_score for the grade it sends to the classroom.
    // No execution_time, which it does not read: the same submissions give the same bytes
    // however busy the machine (issue 47).
    // It prints `message` only for a test in error: a failed case's text and hint go into
    // test_code, which it prints under every test.
    const auto test = [&](const QString &name, const QString &status, double points,
                          const QString &message) {
        const QString command =
            QString("lightbench %1 --seed %2, %3").arg(run.version).arg(run.seed).arg(name);
        return QJsonObject{{"name", name},
                           {"status", status},
                           {"score", points},
                           {"message", message},
                           {"test_code", status == "fail" ? message + "\n" + command : command},
                           {"filename", ""},
                           {"line_no", 0}};
    };
    QJsonObject out{{"version", 1},
                    {"max_score", maxPoints(run)},
                    {"lightbench", run.version},
                    {"seed", double(run.seed)}};
    QJsonArray tests;
    if (!run.error.isEmpty() || rows.empty()) {
        out["status"] = "error";
        tests.append(test("grading", "error", 0, batchErrorText(run)));
    } else {
        const GradedSubmission &row = rows.front();
        const GradingReport &r = row.report;
        out["submission"] = escapedName(row.name);
        if (!r.graded()) {
            out["status"] = "error";
            tests.append(test("grading", "error", 0, notGradedText(r)));
        } else {
            out["status"] = r.passedCount() == int(r.cases.size()) ? "pass" : "fail";
            const std::vector<double> scores = githubCaseScores(run, r);
            for (int k = 0; k < int(r.cases.size()); ++k) {
                const bool passed = r.cases[std::size_t(k)].passed;
                QString message = caseText(run, r, k);
                if (!passed && r.mistake)
                    message += "; hint: " + hintText(r);
                tests.append(test(QString("case %1").arg(k), passed ? "pass" : "fail",
                                  scores[std::size_t(k)], message));
            }
        }
    }
    out["tests"] = tests;
    return json(out);
}

QByteArray gradescopeResults(const GradingRun &run, const std::vector<GradedSubmission> &rows)
{
    QJsonObject out{
        {"visibility", "visible"},
        {"stdout_visibility", "hidden"}, // the batch's own lines: for the teacher
        {"extra_data", QJsonObject{{"lightbench", run.version}, {"seed", double(run.seed)}}}};
    QJsonArray tests;
    if (!run.error.isEmpty() || rows.empty()) {
        out["score"] = 0;
        out["output"] = "lightbench could not grade this submission: " + batchErrorText(run) +
                        "\n" + gradedBy(run);
    } else {
        const GradedSubmission &row = rows.front();
        const GradingReport &r = row.report;
        out["score"] = score(run, r);
        // No execution_time (optional in the specification): the same submissions give the
        // same bytes however busy the machine (issue 47).
        QString output = r.graded() ? summaryLine(run, row) : notGradedText(r);
        output += "\n" + gradedBy(run);
        out["output"] = output;
        if (!r.graded())
            tests.append(QJsonObject{{"name", "grading"},
                                     {"number", "0"},
                                     {"score", 0},
                                     {"max_score", maxPoints(run)},
                                     {"status", "failed"},
                                     {"output", notGradedText(r)},
                                     {"visibility", "visible"}});
        for (int k = 0; r.graded() && k < int(r.cases.size()); ++k) {
            const bool passed = r.cases[std::size_t(k)].passed;
            QString caseOutput = caseText(run, r, k);
            if (!passed && r.mistake)
                caseOutput += "\nHint: " + hintText(r);
            const double points = pointsOfCase(run, k);
            tests.append(QJsonObject{{"name", QString("case %1").arg(k)},
                                     {"number", QString::number(k)},
                                     {"score", passed ? points : 0.0},
                                     {"max_score", points},
                                     {"status", passed ? "passed" : "failed"},
                                     {"output", caseOutput},
                                     {"visibility", "visible"}});
        }
    }
    out["tests"] = tests;
    return json(out);
}

QByteArray codeRunnerOutcome(const GradingRun &run, const std::vector<GradedSubmission> &rows)
{
    // CodeRunner shows prologuehtml and epiloguehtml as HTML: every text in them is escaped,
    // the student's included (a name or a compiler's line quoting "<script>").
    const auto html = [](const QString &text) { return text.toHtmlEscaped(); };
    QJsonObject out{{"epiloguehtml", "<p>" + html(gradedBy(run)) + "</p>"}};
    if (!run.error.isEmpty() || rows.empty()) {
        out["fraction"] = 0;
        out["prologuehtml"] = "<p>lightbench could not grade this answer:</p><pre>" +
                              html(batchErrorText(run)) + "</pre>";
        return json(out);
    }
    const GradedSubmission &row = rows.front();
    const GradingReport &r = row.report;
    if (!r.graded()) {
        out["fraction"] = 0;
        out["prologuehtml"] = "<p>" + html(escapedName(row.name)) + ": " + html(r.status) +
                              "</p><pre>" + html(escapedLines(r.diagnostic)) + "</pre>";
        return json(out);
    }
    const double most = maxPoints(run);
    const bool allPassed = r.passedCount() == int(r.cases.size());
    out["fraction"] = most > 0 ? std::clamp(score(run, r) / most, 0.0, 1.0) : allPassed ? 1 : 0;
    GradedSubmission withoutHint = row; // the hint has a paragraph of its own below
    withoutHint.report.mistake.reset();
    QString prologue = "<p>" + html(summaryLine(run, withoutHint)) + "</p>";
    if (r.mistake)
        prologue += "<p><b>Hint:</b> " + html(hintText(r)) + "</p>";
    out["prologuehtml"] = prologue;
    // "iscorrect": CodeRunner's own column, a tick for 1 and a cross for 0. The header is
    // appended: braces round one QJsonArray copy it with clang (its rows would be the table's).
    QJsonArray table;
    table.append(
        QJsonArray{"iscorrect", "Case", "Pixels within tolerance", "Largest difference", "Points"});
    for (int k = 0; k < int(r.cases.size()); ++k) {
        const CaseResult &c = r.cases[std::size_t(k)];
        const double points = pointsOfCase(run, k);
        table.append(QJsonArray{
            c.passed ? 1 : 0, QString("case %1").arg(k),
            QString::number(100.0 * c.shareWithin, 'f', 1) + '%', QString("%1/255").arg(c.largest),
            QString("%1/%2").arg(pointsText(c.passed ? points : 0.0), pointsText(points))});
    }
    out["testresults"] = table;
    return json(out);
}

} // namespace lb
