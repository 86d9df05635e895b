#pragma once
// What a grading child (`lightbench --grade-one`) says of one submission: one JSON line on
// its standard output. `--grade` reads it for its summary and CSV, the window's Check my work
// for its list of cases; both read it here, so the two cannot drift apart.

#include "grading.h"

#include <QByteArray>
#include <QJsonObject>
#include <QMetaType>
#include <QString>

#include <optional>
#include <vector>

namespace lb {

// A known mistake of the exercise (exercise.h) whose frames match the student's far better
// than the reference's do, in the cases that failed: what the reports say to the student.
struct MistakeMatch
{
    int index = -1; // in the exercise's list of mistakes (the window shows its own language)
    QString name;   // the mistake's short name, as the exercise gives it ("normal matrix")
    QString hint;   // in English: what the reports on the command line say
    double shareWithin = 0; // of the failing cases' pixels, student against the mistake
};

struct GradingReport
{
    QString submission;
    // "graded", "does not compile", "does not link", "refused", "unreadable", "GPU reset", or
    // the exercise's own failures ("no exercise", "no OpenGL", "exercise files", "reference
    // does not build").
    QString status;
    QString diagnostic; // the first diagnostic, "FILE:LINE: message", or why
    std::vector<CaseResult> cases;
    int worstCase = -1; // the case the sheet shows
    QString sheet, sheetError;
    std::optional<MistakeMatch> mistake; // only for a graded submission that failed a case

    bool graded() const { return status == "graded"; }
    int passedCount() const;
    int largest() const;      // over the cases, out of 255
    double meanShare() const; // of the cases' shares within tolerance (0 with none)
};

QJsonObject gradingReportJson(const GradingReport &report);
// The last line of `output` that is a report: a driver may print lines of its own, before or
// after. None when no line is.
std::optional<GradingReport> readGradingReport(const QByteArray &output);

} // namespace lb

Q_DECLARE_METATYPE(lb::GradingReport)
