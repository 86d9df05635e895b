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

// What ends a grading child before its report is whole: its status and diagnostic (none when
// `status` is empty).
struct GradeFailure
{
    QString status, diagnostic;
    explicit operator bool() const { return !status.isEmpty(); }
};

struct MistakeSearch
{
    std::optional<MistakeMatch> match;
    // Set when a mistake cannot be drawn: "mistake does not build" or "mistake refused", and
    // which mistake and why.
    GradeFailure failure;
};

// `stop` says a report with this status and diagnostic and ends the process: a program past
// its bounds never returns from the driver.
using GradeStop = std::function<void(const QString &, const QString &)>;

// Mistake `index`'s program made the one `offscreen` draws with (built and tried within the
// grading bounds; the built-in program for a built-in mistake): no failure, or why the
// mistake cannot be drawn.
GradeFailure useMistakeProgram(OffscreenRenderer &offscreen, const Exercise &exercise, int index,
                               const Scene &firstCase, const GradeStop &stop);
// Mistake `index`'s frame of `gradingCase`, with its program in use.
QImage drawMistake(OffscreenRenderer &offscreen, const Exercise &exercise, int index,
                   const Scene &gradingCase);

// Frames the batch drew once (grade_frames.h): mistake `index`'s frame of each case asked
// for, or nothing when one of them is not there to read.
using PreparedMistakeFrames = std::function<std::optional<std::vector<QImage>>(
    int index, const std::vector<std::size_t> &cases)>;

// Draws with other programs than the student's from then on, unless `prepared` has every
// frame asked for.
MistakeSearch findMistake(OffscreenRenderer &offscreen, const Exercise &exercise,
                          const std::vector<Scene> &cases, const std::vector<FailingCase> &failing,
                          const GradeStop &stop, const PreparedMistakeFrames &prepared = {});

} // namespace lb
