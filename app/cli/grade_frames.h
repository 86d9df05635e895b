#pragma once
// The frames every submission of a batch is measured against, drawn once for the batch: the
// reference's frame of each case and each known mistake's. Before its first submission,
// --grade has them drawn by a child of their own (--grade-prepare DIR, bounded like a
// submission: the teacher's programs are strangers' too) into a private folder, and hands the
// folder to each submission's child (--grade-one ... --grade-frames DIR), which reads them
// instead of building the reference and the mistakes and drawing them again. The folder
// counts only when it is whole and was drawn from the same exercise file and seed (its key,
// written last); anything else (no folder, a file short or missing, a preparation that
// failed) and the child draws its own, as it does alone (Check My Work), so that every
// status and diagnostic stays the child's own.

#include "command_line.h"
#include "grade_mistakes.h"
#include "grading_files.h"

#include <QImage>
#include <QProcess>
#include <QSize>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace lb {

class OffscreenRenderer;

// What a grading child starts from: the exercise, `offscreen` ready with its scene's files,
// and the cases; or the status and diagnostic that end the child ("no exercise", "no
// OpenGL", "exercise files").
struct GradingStart
{
    ExerciseFile exercise;
    std::vector<Scene> cases;
    GradeFailure failure;
};
GradingStart startGrading(const CommandLine &commandLine, OffscreenRenderer &offscreen);

// The reference's frame of each case into `frames`, drawn by the built-in program or by the
// teacher's, built and tried as every submission is. No failure, or "reference refused" or
// "reference does not build" and why.
GradeFailure drawReference(OffscreenRenderer &offscreen, const Exercise &exercise,
                           const std::vector<Scene> &cases, const GradeStop &stop,
                           std::vector<QImage> &frames);

// A folder of frames drawn by --grade-prepare, read by --grade-one.
class PreparedFrames
{
public:
    // Read from when `dir` is not empty and holds the key of this exercise (as `start`
    // parsed it), seed and size.
    PreparedFrames(const QString &dir, const GradingStart &start, std::uint32_t seed);
    // Each case's reference frame, or nothing when one cannot be read whole.
    std::optional<std::vector<QImage>> reference(std::size_t cases) const;
    // Mistake `index`'s frames of the cases asked for, or nothing.
    std::optional<std::vector<QImage>> mistake(int index,
                                               const std::vector<std::size_t> &cases) const;

private:
    std::optional<QImage> read(const QString &name) const;

    QString m_dir;
    QSize m_size;
    bool m_usable = false;
};

// (runGradePrepare, grade.h: --grade-prepare DIR draws the reference's and every mistake's
// frame of every case into DIR, then the key, and prints one line of JSON on stdout:
// {"status":"prepared"} or the failure.)

// Whether drawing the batch's frames first pays: more submissions than run at once (the
// first ones would have drawn them anyway), and room for the (1 + mistakes) x cases frames in
// the temporary folder: at most kMostPreparedBytes, and half the space free there.
bool preparationWorthIt(const GradingSpec &spec, int mistakes, std::size_t submissions,
                        int parallel);
constexpr qint64 kMostPreparedBytes = 1ll << 30;
// Starts --grade-prepare DIR in `preparation` (this program, never the tests' stand-in for
// the children): a boundedChild (bounded_child.h) killed after preparationTimeLimitMs, whose
// finished() always comes; then preparedFrames says whether the frames are there.
void startPreparation(QProcess &preparation, const CommandLine &commandLine, const QString &dir);
bool preparedFrames(QProcess &preparation, int exitCode, QProcess::ExitStatus status);
// How long the preparation may take: a trial and the frames of every case for the reference
// and each mistake ($LIGHTBENCH_GRADE_TIME_LIMIT_MS overrides, as for a submission).
int preparationTimeLimitMs(const GradingSpec &spec, int mistakes);

} // namespace lb
