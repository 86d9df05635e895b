// The shared parts of the reports (points, the texts of a case and a submission), CSV and
// JUnit XML; the platforms' single-submission files are in grading_platforms.cpp.
#include "grading_formats.h"

#include "csv_cell.h"
#include "message_text.h"

#include <QXmlStreamWriter>

#include <cmath>
#include <numeric>

namespace lb {

namespace {

const QStringList kFormatNames{"csv", "junit", "gradescope", "github", "coderunner"};

double rounded(double points)
{
    return std::round(points * 1e4) / 1e4;
}

QString percent(double share)
{
    return QString::number(100.0 * share, 'f', 1) + '%';
}

QString seconds(double s)
{
    return QString::number(std::max(0.0, s), 'f', 3);
}

} // namespace

QStringList reportFormatNames()
{
    return kFormatNames;
}

std::optional<ReportFormat> parseReportFormat(const QString &name)
{
    const int i = kFormatNames.indexOf(name);
    if (i < 0)
        return std::nullopt;
    return ReportFormat(i);
}

bool describesOneSubmission(ReportFormat format)
{
    return format == ReportFormat::Gradescope || format == ReportFormat::GitHub ||
           format == ReportFormat::CodeRunner;
}

double maxPoints(const GradingRun &run)
{
    return rounded(std::accumulate(run.casePoints.begin(), run.casePoints.end(), 0.0));
}

double pointsOfCase(const GradingRun &run, int k)
{
    return k >= 0 && std::size_t(k) < run.casePoints.size() ? run.casePoints[std::size_t(k)] : 0.0;
}

double score(const GradingRun &run, const GradingReport &report)
{
    if (!report.graded())
        return 0.0;
    double sum = 0.0;
    for (int k = 0; k < int(report.cases.size()); ++k)
        if (report.cases[std::size_t(k)].passed)
            sum += pointsOfCase(run, k);
    return rounded(sum);
}

QString pointsText(double points)
{
    return QString::number(rounded(points), 'g', 15);
}

QString caseText(const GradingRun &run, const GradingReport &report, int k)
{
    const CaseResult &c = report.cases.at(std::size_t(k));
    QString text =
        QString("case %1: %2 of pixels within %3/255 (%4 needed), largest difference "
                "%5/255")
            .arg(k)
            .arg(percent(c.shareWithin), QString::number(run.tolerance), percent(run.passShare))
            .arg(c.largest);
    if (c.compared == 0)
        text += ", nothing drawn";
    return text;
}

QString escapedLines(const QString &text)
{
    QStringList lines = text.split('\n');
    for (QString &line : lines)
        line = escapedControls(line);
    return lines.join('\n');
}

QString firstDiagnostic(const GradingReport &report)
{
    const QString text = report.sheetError.isEmpty() ? report.diagnostic : report.sheetError;
    return escapedControls(text.section('\n', 0, 0));
}

QString summaryLine(const GradingRun &run, const GradedSubmission &row)
{
    // Names and diagnostics (which name the student's files) with their controls shown as
    // escapes: a name cannot make a line of its own or recolour the terminal.
    const GradingReport &r = row.report;
    const QString diagnostic = firstDiagnostic(r);
    if (!r.graded())
        return QString("%1: %2%3")
            .arg(escapedName(row.name), r.status,
                 diagnostic.isEmpty() ? QString() : ": " + diagnostic);
    const int passed = r.passedCount(), cases = int(r.cases.size());
    QString line =
        QString("%1: %2, %3/%4 cases passed (%5/%6 points), largest difference "
                "%7/255, %8% of pixels within tolerance%9")
            .arg(escapedName(row.name), passed == cases ? "passed" : "failed",
                 QString::number(passed), QString::number(cases), pointsText(score(run, r)),
                 pointsText(maxPoints(run)), QString::number(r.largest()),
                 QString::number(100.0 * r.meanShare(), 'f', 1),
                 diagnostic.isEmpty() ? QString() : " (" + diagnostic + ")");
    if (r.mistake)
        line += "; hint: " + escapedControls(r.mistake->hint.simplified());
    return line;
}

QByteArray csvReport(const GradingRun &run, const std::vector<GradedSubmission> &rows)
{
    // The original seven columns first, where scripts already read them.
    QString out = "submission,status,cases_passed,cases,worst_difference,mean_share_within,"
                  "first_diagnostic,points,max_points,hint,seed,lightbench\n";
    for (const GradedSubmission &row : rows) {
        const GradingReport &r = row.report;
        const bool graded = r.graded();
        out += QStringList{csvCell(escapedName(row.name)),
                           csvCell(r.status),
                           graded ? QString::number(r.passedCount()) : QString(),
                           graded ? QString::number(r.cases.size()) : QString(),
                           graded ? QString::number(r.largest()) : QString(),
                           graded ? QString::number(r.meanShare(), 'f', 4) : QString(),
                           csvCell(firstDiagnostic(r)),
                           pointsText(score(run, r)),
                           pointsText(maxPoints(run)),
                           csvCell(r.mistake ? escapedControls(r.mistake->hint.simplified())
                                             : QString()),
                           QString::number(run.seed),
                           csvCell(run.version)}
                   .join(',') +
               "\n";
    }
    return out.toUtf8();
}

QByteArray junitReport(const GradingRun &run, const std::vector<GradedSubmission> &rows)
{
    int tests = 0, failures = 0, errors = 0;
    double time = 0;
    for (const GradedSubmission &row : rows) {
        const GradingReport &r = row.report;
        tests += r.graded() ? int(r.cases.size()) : 1;
        failures += r.graded() ? int(r.cases.size()) - r.passedCount() : 0;
        errors += r.graded() ? 0 : 1;
        time += row.seconds;
    }
    QByteArray bytes;
    QXmlStreamWriter xml(&bytes); // escapes what it writes; UTF-8
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    xml.writeStartElement("testsuites");
    xml.writeAttribute("name", "lightbench --grade");
    xml.writeAttribute("tests", QString::number(tests));
    xml.writeAttribute("failures", QString::number(failures));
    xml.writeAttribute("errors", QString::number(errors));
    xml.writeAttribute("time", seconds(time));
    for (const GradedSubmission &row : rows) {
        const GradingReport &r = row.report;
        const QString name = escapedName(row.name);
        const int cases = r.graded() ? int(r.cases.size()) : 1;
        xml.writeStartElement("testsuite");
        xml.writeAttribute("name", name);
        xml.writeAttribute("tests", QString::number(cases));
        xml.writeAttribute("failures", QString::number(r.graded() ? cases - r.passedCount() : 0));
        xml.writeAttribute("errors", QString::number(r.graded() ? 0 : 1));
        xml.writeAttribute("skipped", "0");
        xml.writeAttribute("time", seconds(row.seconds));
        xml.writeStartElement("properties");
        for (const auto &[key, value] :
             {std::pair<QString, QString>{"seed", QString::number(run.seed)},
              {"lightbench", run.version},
              {"points", pointsText(score(run, r))},
              {"max_points", pointsText(maxPoints(run))}}) {
            xml.writeStartElement("property");
            xml.writeAttribute("name", key);
            xml.writeAttribute("value", value);
            xml.writeEndElement();
        }
        xml.writeEndElement(); // properties
        // The child times the submission, not its cases: each gets an even share.
        const QString caseTime = seconds(row.seconds / cases);
        if (!r.graded()) {
            xml.writeStartElement("testcase");
            xml.writeAttribute("classname", name);
            xml.writeAttribute("name", "grading");
            xml.writeAttribute("time", caseTime);
            xml.writeStartElement("error");
            xml.writeAttribute("message", r.status);
            xml.writeAttribute("type", r.status);
            xml.writeCharacters(escapedLines(r.diagnostic));
            xml.writeEndElement();
            xml.writeEndElement();
        }
        for (int k = 0; r.graded() && k < cases; ++k) {
            xml.writeStartElement("testcase");
            xml.writeAttribute("classname", name);
            xml.writeAttribute("name", QString("case %1").arg(k));
            xml.writeAttribute("time", caseTime);
            if (!r.cases[std::size_t(k)].passed) {
                QString message = caseText(run, r, k);
                if (r.mistake)
                    message += "; hint: " + escapedControls(r.mistake->hint.simplified());
                xml.writeStartElement("failure");
                xml.writeAttribute("message", message);
                xml.writeAttribute("type", "failed");
                xml.writeCharacters(message);
                xml.writeEndElement();
            }
            xml.writeEndElement(); // testcase
        }
        xml.writeEndElement(); // testsuite
    }
    xml.writeEndElement(); // testsuites
    xml.writeEndDocument();
    return bytes;
}

QByteArray reportBytes(ReportFormat format, const GradingRun &run,
                       const std::vector<GradedSubmission> &rows)
{
    switch (format) {
    case ReportFormat::Csv:
        return csvReport(run, rows);
    case ReportFormat::JUnit:
        return junitReport(run, rows);
    case ReportFormat::Gradescope:
        return gradescopeResults(run, rows);
    case ReportFormat::GitHub:
        return githubResult(run, rows);
    case ReportFormat::CodeRunner:
        return codeRunnerOutcome(run, rows);
    }
    return {};
}

} // namespace lb
