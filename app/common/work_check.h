#pragma once
// Check my work: the open exercise's cases drawn with the student's program and with the
// reference, in a grading child (`lightbench --grade-one`, as `--grade` runs one per
// submission). The window never waits, and a program that hangs or brings the driver down
// costs the child only: after the time limit it is killed and the check says so.

#include "exercise.h"
#include "grading_report.h"
#include "scene.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

class QProcess;
class QTemporaryDir;

namespace lb {

// The program a grading child runs: $LIGHTBENCH_GRADE_PROGRAM (a test's stand-in, or the
// workbench itself for a test's window), else this program.
QString gradingChildProgram();
// How long one submission may take: its process, its trial and its frames, and the known
// mistakes drawn for a failing one.
// $LIGHTBENCH_GRADE_TIME_LIMIT_MS overrides.
int gradingTimeLimitMs(const GradingSpec &spec, int mistakes);
// Why a grading child that printed no report ended: "killed by signal 11 (Segmentation
// fault)", "exit code 3", or "PROGRAM: why" when it could not start. --grade and Check My
// Work both say it.
QString endedWithoutReport(const QProcess &child);

class WorkCheck : public QObject
{
    Q_OBJECT
public:
    explicit WorkCheck(QObject *parent = nullptr);
    ~WorkCheck() override;

    // Checks the program (vertex, fragment) against `exercise` on its scene `base`; a check
    // still running is cancelled. Returns an empty string, or why it could not start (then
    // no finished() follows).
    QString start(const Scene &base, const Exercise &exercise, const QString &vertex,
                  const QString &fragment);
    void cancel();
    bool isRunning() const { return m_process != nullptr; }
    // The scenes of the last check's cases (gradingCases with the seed --grade uses by
    // default), so that a case can be shown in the window as it was graded.
    const std::vector<Scene> &cases() const { return m_cases; }
    static constexpr std::uint32_t kSeed = 1;

signals:
    // The child's report; a child that timed out or crashed gives a report with that status.
    void finished(const lb::GradingReport &report);

private:
    void ended();
    QProcess *m_process = nullptr;
    std::unique_ptr<QTemporaryDir> m_dir;
    std::vector<Scene> m_cases;
    bool m_timedOut = false;
    int m_limitMs = 0;
};

} // namespace lb
