#include "work_check.h"

#include "mistake_match.h"

#include "safe_write.h"
#include "scene_file.h"
#include "signal_names.h"

#include <QCoreApplication>
#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QTimer>

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
    // Two frames a case (reference and student), each within the trial's budget; for a
    // failing submission, each known mistake's trial and its frames of the failing cases.
    const int mistakeFrames = mistakes * (std::min(spec.cases, kMaxMistakeCases) + 1);
    return asked > 0 ? asked
                     : int(30000 + kGradingTrialBudgetMs * (2 * spec.cases + mistakeFrames));
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

WorkCheck::WorkCheck(QObject *parent) : QObject(parent), m_timer(new QTimer(this))
{
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, [this] {
        m_timedOut = true;
        if (m_process)
            m_process->kill(); // finished() follows
    });
}

WorkCheck::~WorkCheck()
{
    cancel();
}

void WorkCheck::cancel()
{
    m_timer->stop();
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
    auto *p = new QProcess(this);
    m_process = p;
    // Queued, and only for this process: an end posted by a check cancelled since must not
    // end the one started after it.
    const auto ended = [this, p] {
        if (p == m_process)
            this->ended();
    };
    connect(p, &QProcess::finished, this, ended, Qt::QueuedConnection);
    connect(p, &QProcess::errorOccurred, this, [ended, this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart) // no finished() follows: say it ended
            QTimer::singleShot(0, this, ended);
    });
    m_process->start(gradingChildProgram(),
                     {"--grade-one", submission, "--grade-name", tr("your program"), "--exercise",
                      exercisePath, "--seed", QString::number(kSeed)});
    m_timer->start(m_limitMs);
    return {};
}

void WorkCheck::ended()
{
    QProcess *p = m_process;
    if (!p)
        return; // cancelled meanwhile
    m_process = nullptr;
    m_timer->stop();
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
