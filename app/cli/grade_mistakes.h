#pragma once
// The grading child's hint (issue 33, part 3): a submission that failed some cases has those
// cases drawn with each of the exercise's known mistakes too, and the mistake whose frames
// match the student's far better than the reference's (mistake_match.h) is named in its
// report. A mistake's program is a stranger's as much as the reference's is: built and tried
// under the same bounds, and one that does not build or is refused is the exercise's fault.

#include "exercise.h"
#include "grading.h"
#include "grading_report.h"
#include "scene.h"

#include <QImage>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace lb {

class OffscreenRenderer;

struct FailingCase
{
    std::size_t index; // in the cases
    QImage student;    // the student's frame
    QImage reference;  // the reference's
    CaseResult result; // against the reference
};

struct MistakeSearch
{
    std::optional<MistakeMatch> match;
    // Set when a mistake cannot be drawn: "mistake does not build" or "mistake refused", and
    // which mistake and why.
    QString failure, diagnostic;
};

// `stop` says a report with this status and diagnostic and ends the process: a program past
// its bounds never returns from the driver. Draws with other programs than the student's from
// then on.
MistakeSearch findMistake(OffscreenRenderer &offscreen, const Exercise &exercise,
                          const std::vector<Scene> &cases, const std::vector<FailingCase> &failing,
                          const std::function<void(const QString &, const QString &)> &stop);

} // namespace lb
