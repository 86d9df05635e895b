#include "work_check.h"

#include "bounded_child.h"
#include "mistake_match.h"

#include "safe_write.h"
#include "scene_file.h"
#include "signal_names.h"

#include <QCoreApplication>
#include <QDir>
#include <QProcess>
#include <QTemporaryDir>

#include <algorithm>

namespace lb {

QString gradingChildProgram()
{
    const QString program = qEnvironmentVariable("LIGHTBENCH_GRADE_PROGRAM");
    return program.isEmpty() ? QCoreApplication::applicationFilePath() : program;
}

int gradingTimeLimitMs(const GradingSpec &spec, int mistakes)
{
    const int asked = qEnvironmentVariableIntValue("LIGHTBENCH_GRADE_TIME_LIMIT_MS");
    // Two frames a case (reference and student), each within the exercise's frame budget
    // (processor time: about the wall time two busy programs leave llvmpipe's threads); for a
    // failing submission, each known mistake's trial and its frames of the failing cases.
    const int mistakeFrames = mistakes * (std::min(spec.cases, kMaxMistakeCases) + 1);
    return asked > 0 ? asked : int(30000 + spec.frameBudgetMs() * (2 * spec.cases + mistakeFrames));
}

QString endedWithoutReport(const QProcess &child)
{
    // WorkCheck's words: English from --grade (no translator), translated in the window.
    if (child.error() == QProcess::FailedToStart)
        return QString("%1: %2").arg(child.program(), child.errorString());
    if (child.exitStatus() == QProcess::CrashExit) // the exit code is the signal then
        //: %2 is the C library's name of the signal, in English ("Segmentation fault")
        return WorkCheck::tr("killed by signal %1 (%2)")
            .arg(child.exitCode())
            .arg(platform::signalName(child.exitCode()));
    return WorkCheck::tr("exit code %1").arg(child.exitCode());
}

WorkCheck::WorkCheck(QObject *parent) : QObject(parent) {}

WorkCheck::~WorkCheck()
{
    cancel();
}

void WorkCheck::cancel()
{
    if (!m_process)
        return;
    QProcess *p = m_process;
    m_process = nullptr; // its finished() is no longer ours
    p->disconnect(this);
    // Killed and let go without waiting (a child stuck in the driver must not stall the
    // window); its folder goes with it.
    QTemporaryDir *dir = m_dir.release();
    connect(p, &QObject::destroyed, [dir] { delete dir; });
    connect(p, &QProcess::finished, p, &QObject::deleteLater);
    if (p->state() == QProcess::NotRunning)
        p->deleteLater();
    else
        p->kill();
}

QString WorkCheck::start(const Scene &base, const Exercise &exercise, const QString &vertex,
                         const QString &fragment)
{
    cancel();
    // The exercise's scene and the program as files, as a teacher's batch has them.
    m_dir = std::make_unique<QTemporaryDir>(QDir::temp().filePath("lightbench-check-XXXXXX"));
    if (!m_dir->isValid())
        return tr("no temporary folder for the check: %1").arg(m_dir->errorString());
    const QDir dir(m_dir->path());
    const QString exercisePath = dir.filePath("exercise.json");
    Exercise graded = exercise;
    graded.unread = QJsonValue::Undefined;
    if (QString error = writeSceneFile(exercisePath, SceneFile{base, std::nullopt, graded});
        !error.isEmpty())
        return error;
    const QString submission = dir.filePath("shader");
    if (QString error = writeFilesSafely(
            {{submission + ".vert", vertex.toUtf8()}, {submission + ".frag", fragment.toUtf8()}});
        !error.isEmpty())
        return error;

    m_cases = gradingCases(base, exercise.grading, kSeed);
    m_timedOut = false;
    m_limitMs = gradingTimeLimitMs(exercise.grading, int(exercise.mistakes.size()));
    // Only for this process: a check cancelled since (killed, let go) must not touch the one
    // started after it.
    QProcess *p = boundedChild(this, m_limitMs, [this](QProcess *timedOut) {
        if (timedOut == m_process)
            m_timedOut = true;
    });
    m_process = p;
    // Queued: a failure to start ends it from inside start().
    connect(
        p, &QProcess::finished, this,
        [this, p] {
            if (p == m_process)
                ended();
        },
        Qt::QueuedConnection);
    p->start(gradingChildProgram(), {"--grade-one", submission, "--grade-name", tr("your program"),
                                     "--exercise", exercisePath, "--seed", QString::number(kSeed)});
    return {};
}

void WorkCheck::ended()
{
    QProcess *p = m_process;
    if (!p)
        return; // cancelled meanwhile
    m_process = nullptr;
    GradingReport report;
    if (m_timedOut) {
        report.status = "timed out";
        report.diagnostic = tr("more than %1 s").arg(m_limitMs / 1000.0, 0, 'f', 1);
    } else if (const std::optional<GradingReport> r =
                   readGradingReport(p->readAllStandardOutput())) {
        report = *r;
    } else {
        report.status = p->error() == QProcess::FailedToStart ? "could not start" : "crashed";
        report.diagnostic = endedWithoutReport(*p);
    }
    p->deleteLater();
    m_dir.reset();
    emit finished(report);
}

} // namespace lb
