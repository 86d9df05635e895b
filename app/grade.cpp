#include "grade.h"

#include "csv_cell.h"
#include "grading_files.h"
#include "grading_report.h"
#include "message_text.h"
#include "safe_write.h"
#include "stop_signals.h"
#include "submission.h"
#include "work_check.h"

#include <QDir>
#include <QEventLoop>
#include <QProcess>
#include <QSet>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <functional>

namespace lb {

namespace {

// What a child says when the exercise, not the submission, is at fault: the batch stops.
const QStringList kBatchFailures{"no exercise",       "no OpenGL",
                                 "exercise files",    "reference does not build",
                                 "reference refused", "mistake does not build",
                                 "mistake refused"};

// What one child said, or what became of it.
struct Graded
{
    QString name;
    QString status; // "graded", "does not compile", "does not link", "refused", "timed out", ...
    QString diagnostic;
    bool sheetFailed = false; // graded, but its sheet could not be written (the diagnostic)
    int cases = 0, passed = 0, worst = 0;
    double meanShare = 0.0;
};

Graded fromReport(const GradingReport &r)
{
    Graded g;
    g.status = r.status;
    g.diagnostic = r.sheetError.isEmpty() ? r.diagnostic : r.sheetError;
    g.sheetFailed = !r.sheetError.isEmpty();
    g.cases = int(r.cases.size());
    g.passed = r.passedCount();
    g.worst = r.largest();
    g.meanShare = r.meanShare();
    return g;
}

QString summaryLine(const Graded &g)
{
    // Names and diagnostics (which name the student's files) with their controls shown as
    // escapes: a name cannot make a line of its own or recolour the terminal.
    const QString diagnostic = escapedControls(g.diagnostic.section('\n', 0, 0));
    if (g.status != "graded")
        return QString("%1: %2%3")
            .arg(escapedName(g.name), g.status,
                 diagnostic.isEmpty() ? QString() : ": " + diagnostic);
    return QString("%1: %2, %3/%4 cases passed, largest difference %5/255, %6% of pixels within "
                   "tolerance%7")
        .arg(escapedName(g.name), g.passed == g.cases ? "passed" : "failed")
        .arg(g.passed)
        .arg(g.cases)
        .arg(g.worst)
        .arg(100.0 * g.meanShare, 0, 'f', 1)
        .arg(diagnostic.isEmpty() ? QString() : " (" + diagnostic + ")");
}

QString csv(const std::vector<Graded> &rows)
{
    QString out = "submission,status,cases_passed,cases,worst_difference,mean_share_within,"
                  "first_diagnostic\n";
    for (const Graded &g : rows) {
        const bool graded = g.status == "graded";
        out += QStringList{csvCell(escapedName(g.name)),
                           csvCell(g.status),
                           graded ? QString::number(g.passed) : QString(),
                           graded ? QString::number(g.cases) : QString(),
                           graded ? QString::number(g.worst) : QString(),
                           graded ? QString::number(g.meanShare, 'f', 4) : QString(),
                           csvCell(escapedControls(g.diagnostic.section('\n', 0, 0)))}
                   .join(',') +
               "\n";
    }
    return out;
}

// Names as the report gives them: a submission's own, made unique ("lighting", "lighting-2")
// so that rows and sheets are told apart.
QStringList uniqueNames(const QStringList &names)
{
    QStringList unique;
    QSet<QString> taken;
    for (QString name : names) {
        if (name.isEmpty())
            name = "submission";
        QString candidate = name;
        for (int n = 2; taken.contains(candidate); ++n)
            candidate = QString("%1-%2").arg(name).arg(n);
        taken.insert(candidate);
        unique << candidate;
    }
    return unique;
}

// "--report: PATH: why" when a result of the batch could not be written; empty when all can.
QString outputsUnwritable(const CommandLine &cl, const QStringList &names)
{
    if (!cl.reportPath.isEmpty())
        if (const QString why = unwritableTarget(cl.reportPath); !why.isEmpty())
            return "--report: " + why;
    if (cl.sheetsDir.isEmpty())
        return {};
    if (!QDir().mkpath(cl.sheetsDir))
        return QString("--sheets: %1: cannot make the folder").arg(cl.sheetsDir);
    for (const QString &name : names)
        if (const QString why = unwritableTarget(gradingSheetPath(cl.sheetsDir, name));
            !why.isEmpty())
            return "--sheets: " + why;
    return {};
}

QString signalName(int signal)
{
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
#ifdef SIGHUP // POSIX's, not standard C's
    case SIGHUP:
        return "SIGHUP";
#endif
    }
    return QString("signal %1").arg(signal);
}

} // namespace

int runGrade(const CommandLine &cl)
{
#ifdef SIGPIPE // POSIX's: stdout piped into a reader that went; the CSV still counts
    std::signal(SIGPIPE, SIG_IGN);
#endif
    const ExerciseFile e = readExerciseFile(cl.exercisePath);
    if (!e.error.isEmpty()) {
        printLine("lightbench: --exercise: " + e.error, stderr);
        return 2;
    }
    if (!e.ignored.isEmpty())
        printLine(QString("lightbench: --exercise: %1: ignored: %2")
                      .arg(cl.exercisePath, summarisedList(e.ignored, "; ")),
                  stderr);
    const int cases = e.file.exercise->grading.cases;
    // Time for one submission: its process, its trial and its frames; a hang ends here.
    const int limitMs = gradingTimeLimitMs(cases);

    const QStringList paths = distinctSubmissions(cl.submissions);
    std::vector<Graded> rows(std::size_t(paths.size()));
    std::vector<bool> finished(rows.size(), false);
    QStringList names;
    std::vector<Submission> submissions;
    for (const QString &path : paths) {
        submissions.push_back(readSubmission(path));
        names << submissions.back().name;
    }
    names = uniqueNames(names);

    // Where the results go is checked before the first submission is graded: a FIFO, a
    // device or a folder in their place, or a folder that cannot take them, ends the batch.
    if (const QString error = outputsUnwritable(cl, names); !error.isEmpty()) {
        printLine("lightbench: " + error, stderr);
        return 2;
    }

    bool anyUnreadable = false;
    std::vector<int> toRun;
    for (int i = 0; i < int(submissions.size()); ++i) {
        Graded &row = rows[std::size_t(i)];
        row.name = names[i];
        if (!submissions[std::size_t(i)].error.isEmpty()) {
            printLine("lightbench: " + escapedControls(submissions[std::size_t(i)].error), stderr);
            row.status = "unreadable";
            row.diagnostic = submissions[std::size_t(i)].error;
            finished[std::size_t(i)] = true;
            anyUnreadable = true;
        } else {
            toRun.push_back(i);
        }
    }

    // Each line is printed once its submission and all before it are done, and the CSV is
    // written again after each: what finished is kept whenever the batch ends.
    std::size_t printed = 0;
    const auto printFinished = [&](bool all) {
        for (; printed < rows.size(); ++printed) {
            if (finished[printed])
                printLine(summaryLine(rows[printed]), stdout);
            else if (!all)
                break;
        }
    };
    QString reportError; // the last write's, said once until it changes
    const auto writeReport = [&] {
        if (cl.reportPath.isEmpty())
            return;
        std::vector<Graded> done;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (finished[i])
                done.push_back(rows[i]);
        const QString error = writeFileSafely(cl.reportPath, csv(done).toUtf8());
        if (!error.isEmpty() && error != reportError)
            printLine("lightbench: --report: " + error, stderr);
        reportError = error;
    };
    writeReport();
    if (!reportError.isEmpty())
        return 1; // nothing graded yet: no time lost on a batch whose report cannot be kept

    // One process per core (two here, at most four): each submission in a process of its
    // own. LIGHTBENCH_GRADE_PROCESSES sets how many (bench/grade.sh compares).
    const int processes = qEnvironmentVariableIntValue("LIGHTBENCH_GRADE_PROCESSES");
    const int parallel = processes > 0 ? std::min(processes, 16)
                                       : std::max(1, std::min(QThread::idealThreadCount(), 4));
    QEventLoop loop;
    QObject children; // owns the processes: each goes with it, whatever the loop left undone
    StopSignals stop;
    int stoppedBy = 0;
    std::size_t next = 0;
    int running = 0;
    QString batchFailure; // the exercise's fault, said by a child: no more are started
    std::function<void()> startMore;
    const auto ended = [&](int i, QProcess *p) {
        Graded &row = rows[std::size_t(i)];
        const std::optional<GradingReport> report = readGradingReport(p->readAllStandardOutput());
        p->deleteLater();
        --running;
        // A child that ended without a report while the batch is being stopped was stopped
        // with it (Ctrl+C reaches the whole process group): it did not finish.
        const bool stopped = StopSignals::received() && !report;
        if (stopped) {
        } else if (row.status == "timed out") {
            row.diagnostic = QString("more than %1 s").arg(limitMs / 1000.0, 0, 'f', 1);
        } else if (report) { // a result printed counts, whatever came after it
            const QString name = row.name;
            row = fromReport(*report);
            row.name = name;
            if (kBatchFailures.contains(row.status) && batchFailure.isEmpty())
                batchFailure = row.status + ": " + row.diagnostic.section('\n', 0, 0);
        } else {
            row.status = "crashed";
            const QString said = QString::fromUtf8(p->readAllStandardError())
                                     .split('\n')
                                     .filter("lightbench")
                                     .value(0)
                                     .trimmed();
            row.diagnostic = (p->error() == QProcess::FailedToStart ? "could not start: " : "") +
                             endedWithoutReport(*p);
            if (!said.isEmpty())
                row.diagnostic += "; " + said;
        }
        if (!stopped && batchFailure.isEmpty()) {
            finished[std::size_t(i)] = true;
            printFinished(false);
            writeReport();
        }
        startMore(); // or the end, when nothing is left to start and nothing runs
    };
    startMore = [&] {
        while (running < parallel && next < toRun.size() && batchFailure.isEmpty() &&
               !StopSignals::received()) {
            const int i = toRun[next++];
            auto *p = new QProcess(&children);
            QStringList args{
                "--grade-one", paths[i],        "--grade-name", names[i],
                "--exercise",  cl.exercisePath, "--seed",       QString::number(cl.seed)};
            if (!cl.sheetsDir.isEmpty())
                args << "--sheets" << cl.sheetsDir;
            auto *timer = new QTimer(p);
            timer->setSingleShot(true);
            QObject::connect(timer, &QTimer::timeout, p, [&rows, i, p] {
                rows[std::size_t(i)].status = "timed out";
                p->kill();
            });
            // Queued: a process that fails to start says so from inside start(), before
            // the loop runs.
            QObject::connect(
                p, &QProcess::finished, &loop,
                [&, i, p, timer] {
                    timer->stop();
                    ended(i, p);
                },
                Qt::QueuedConnection);
            QObject::connect(p, &QProcess::errorOccurred, p, [p](QProcess::ProcessError error) {
                if (error == QProcess::FailedToStart) // no finished() follows: say it ended
                    emit p->finished(-1, QProcess::CrashExit);
            });
            ++running;
            // LIGHTBENCH_GRADE_PROGRAM stands in for this program in the children (the tests
            // give one that crashes, chatters or is not there).
            p->start(gradingChildProgram(), args);
            timer->start(limitMs);
        }
        if (running == 0) // a batch failure or a stop with nothing left running
            loop.quit();
    };
    QObject::connect(&stop, &StopSignals::stopRequested, &loop, [&](int signal) {
        stoppedBy = signal;
        loop.quit();
    });
    if (!toRun.empty()) {
        QTimer::singleShot(0, &loop, startMore); // from inside the loop, so its quit counts
        loop.exec();
    }
    stoppedBy = StopSignals::received(); // also one that came while the loop was ending
    if (stoppedBy) {
        // No child is left running: each is killed and waited for before the batch ends.
        for (QProcess *p : children.findChildren<QProcess *>()) {
            p->disconnect();
            p->kill();
            p->waitForFinished(5000);
        }
        printFinished(true);
        const int done = int(std::count(finished.begin(), finished.end(), true));
        printLine(QString("lightbench: --grade: stopped by %1 with %2 of %3 submissions done%4")
                      .arg(signalName(stoppedBy))
                      .arg(done)
                      .arg(rows.size())
                      .arg(cl.reportPath.isEmpty()
                               ? QString()
                               : QString("; %1 holds their rows").arg(cl.reportPath)),
                  stderr);
        return StopSignals::exitCodeFor(stoppedBy);
    }
    if (!batchFailure.isEmpty()) {
        printLine(QString("lightbench: --exercise: %1: %2").arg(cl.exercisePath, batchFailure),
                  stderr);
        return 2;
    }
    printFinished(true);
    const bool sheetFailed =
        std::any_of(rows.begin(), rows.end(), [](const Graded &g) { return g.sheetFailed; });
    if (!reportError.isEmpty() || sheetFailed)
        return 1; // each line said which file and why
    return anyUnreadable ? 2 : 0;
}

} // namespace lb
