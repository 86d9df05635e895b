#pragma once
// The reports of a grading batch (`--grade --report FILE --report-format WORD`), each in the
// shape its reader takes: CSV for a teacher's spreadsheet, JUnit XML for GitLab and Jenkins,
// and the result files of GitHub Classroom, Gradescope and Moodle CodeRunner, which grade one
// student per run. Pure functions from the graded rows to bytes, so that every format gives
// the same score and a test can feed them any report; the batch (app/cli/grade.cpp) writes them.
//
// Everything a student controls (a submission's name, the compiler's message quoting their
// line, a known mistake's hint) is written with its controls escaped (message_text.h), and
// escaped again as the format needs: XML by QXmlStreamWriter, HTML for CodeRunner, JSON by
// QJsonDocument, CSV cells by csvCell().

#include "grading_report.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace lb {

enum class ReportFormat { Csv, JUnit, Gradescope, GitHub, CodeRunner };
// As --report-format spells them, in the order above.
QStringList reportFormatNames();
std::optional<ReportFormat> parseReportFormat(const QString &name);
// GitHub Classroom, Gradescope and CodeRunner grade one student per run: their files describe
// one submission.
bool describesOneSubmission(ReportFormat format);

// One submission as the batch finished it.
struct GradedSubmission
{
    QString name; // unique within the batch (the report's and the sheet's name), as spelt
    // The child's report; for one that timed out, crashed or could not be read, its status
    // ("timed out", "crashed", "unreadable") and diagnostic alone.
    GradingReport report;
    double seconds = 0; // from its child's start to its end
};

// What is the same for every row of a run.
struct GradingRun
{
    std::vector<double> casePoints; // what each case is worth (the exercise's grading.points)
    double passShare = 0.99;        // of pixels within the tolerance, for a case to pass
    int tolerance = 2;              // out of 255
    std::uint32_t seed = 1;
    QString version; // lightbench's
    // Why the batch graded nobody (a faulty exercise, more submissions than the format takes):
    // CodeRunner reads no stderr, so its JSON says it.
    QString error;
};

// The most a submission can score: the sum of the cases' points.
double maxPoints(const GradingRun &run);
// What case k is worth (0 past the exercise's cases).
double pointsOfCase(const GradingRun &run, int k);
// The points of its passed cases; 0 when it was not graded. Rounded to 1/10000 of a point,
// so that sums of equal shares (100 / 3) come out whole.
double score(const GradingRun &run, const GradingReport &report);
// Points as written: "5", "33.3333".
QString pointsText(double points);
// "case 3: 71.5% of pixels within 2/255 (99.0% needed), largest difference 104/255"
QString caseText(const GradingRun &run, const GradingReport &report, int k);
// The line --grade prints for a submission: "correct: passed, 20/20 cases passed (100/100
// points), largest difference ..." or "syntax: does not compile: syntax.frag:26: ...", with
// the known mistake's hint when there is one. One line: controls escaped.
QString summaryLine(const GradingRun &run, const GradedSubmission &row);
// A multi-line text (a compiler's log) with each line's controls escaped and its line breaks
// kept, for the formats that show it whole.
QString escapedLines(const QString &text);
// The diagnostic a report shows first: the sheet's error for a graded submission whose sheet
// could not be written, else the child's first diagnostic line; controls escaped.
QString firstDiagnostic(const GradingReport &report);

// The report of `rows` (the submissions finished so far, in the order given) in `format`.
QByteArray reportBytes(ReportFormat format, const GradingRun &run,
                       const std::vector<GradedSubmission> &rows);

// Each format on its own (reportBytes picks one).
// One row per submission, with points, the first diagnostic, the hint, the seed and the
// version in columns of their own (a spreadsheet reads no comment lines).
QByteArray csvReport(const GradingRun &run, const std::vector<GradedSubmission> &rows);
// <testsuites> with one <testsuite> per submission, one <testcase> per case (a <failure>
// when it failed); a submission that was not graded has one <testcase> with an <error>.
QByteArray junitReport(const GradingRun &run, const std::vector<GradedSubmission> &rows);
// GitHub Classroom's runner result, as classroom-resources/autograding-grading-reporter reads
// it from a step's `result` output (base64 of these bytes): {"version": 1, "status":
// "pass"|"fail"|"error", "max_score", "tests": [{"name", "status", "score", "message",
// "test_code", "filename", "line_no", "execution_time"}]}. The first row only.
QByteArray githubResult(const GradingRun &run, const std::vector<GradedSubmission> &rows);
// Gradescope's results.json: "score", "execution_time", "output", "visibility",
// "stdout_visibility", "extra_data", "tests": [{"name", "number", "score", "max_score",
// "status", "output", "visibility"}]. The first row only.
QByteArray gradescopeResults(const GradingRun &run, const std::vector<GradedSubmission> &rows);
// What a CodeRunner combinator template grader prints: {"fraction", "prologuehtml",
// "testresults", "epiloguehtml"}; `run.error` or no row: fraction 0 and why. The first row only.
QByteArray codeRunnerOutcome(const GradingRun &run, const std::vector<GradedSubmission> &rows);

} // namespace lb
