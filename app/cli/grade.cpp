#include "grade.h"

#include "lightbench_version.h"

#include "bounded_child.h"
#include "grade_frames.h"
#include "grade_frames_folder.h"
#include "grade_outputs.h"
#include "grading_files.h"
#include "grading_formats.h"
#include "grading_report.h"
#include "message_text.h"
#include "safe_write.h"
#include "stop_signals.h"
#include "submission.h"
#include "work_check.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QLockFile>
#include <QProcess>
#include <QSet>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <functional>
#include <memory>

namespace lb {

namespace {

// What a child says when the exercise, not the submission, is at fault: the batch stops.
const QStringList kBatchFailures{"no exercise",       "no OpenGL",
                                 "exercise files",    "reference does not build",
                                 "reference refused", "mistake does not build",
                                 "mistake refused"};

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
            candidate = name + QString("-%1").arg(n);
        taken.insert(candidate);
        unique << candidate;
    }
    return unique;
}

// "--report: PATH: why" when a result of the batch could not be written; empty when all can.
QString outputsUnwritable(const CommandLine &cl)
{
    if (!cl.reportPath.isEmpty() && cl.reportPath != "-")
        if (const QString why = unwritableTarget(cl.reportPath); !why.isEmpty())
            return "--report: " + why;
    if (cl.sheetsDir.isEmpty())
        return {};
    if (!QDir().mkpath(cl.sheetsDir))
        return QString("--sheets: %1: cannot make the folder").arg(cl.sheetsDir);
    if (const QString why = unwritableTarget(sheetListPath(cl.sheetsDir)); !why.isEmpty())
        return "--sheets: " + why;
    // Each student's sheet is that student's: one that cannot be written (a FIFO in its
    // place) fails that sheet when it is written, said on its line, never the class.
    return {};
}

// Locks `lockPath` for this batch's output `target` (into `locks`, held until they go); the
// reason when another batch holds it. Two batches writing one report each rewrote it after
// every submission, and one's rows were lost with both exiting 0. A lock whose batch is gone
// (killed) is taken over (QLockFile checks its pid; never by age: a class takes minutes).
QString lockOutput(const QString &option, const QString &target, const QString &lockPath,
                   std::vector<std::unique_ptr<QLockFile>> &locks)
{
    auto l = std::make_unique<QLockFile>(lockPath);
    l->setStaleLockTime(0);
    if (l->tryLock(0)) {
        locks.push_back(std::move(l));
        return {};
    }
    // A lock that cannot be made (a full disk) guards nothing, and stops nothing: the
    // report's own write then says what is wrong, as it did.
    if (l->error() != QLockFile::LockFailedError)
        return {};
    qint64 pid = 0;
    QString host, app;
    l->getLockInfo(&pid, &host, &app);
    return QString("%1: %2 is being written by another batch (process %3); wait for it or "
                   "choose another")
        .arg(option, echoedPath(target), QString::number(pid));
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

GradingRun batchRun(const CommandLine &cl)
{
    GradingRun run;
    run.seed = cl.seed;
    run.version = QStringLiteral(LIGHTBENCH_VERSION);
    return run;
}

} // namespace

void quietStandardErrorForGrade(const CommandLine &cl)
{
    // CodeRunner takes any output on stderr for a failure of the grader itself: nothing goes
    // there (the children's is read by the batch), and what would is said in the JSON.
    // Should the null device fail to open, freopen closes stderr: quiet all the same.
    if (cl.grade && ReportFormat(cl.reportFormat) == ReportFormat::CodeRunner) {
        FILE *const quiet = std::freopen(qPrintable(QProcess::nullDevice()), "w", stderr);
        (void)quiet;
    }
}

int failGrade(const CommandLine &cl, const QString &error, int exitCode)
{
    printLine("lightbench: " + error, stderr);
    BatchReport(cl.reportPath, ReportFormat(cl.reportFormat), batchRun(cl)).writeBatchError(error);
    return exitCode;
}

int runGrade(const CommandLine &cl)
{
#ifdef SIGPIPE // POSIX's: stdout piped into a reader that went; the CSV still counts
    std::signal(SIGPIPE, SIG_IGN);
#endif
    const auto format = ReportFormat(cl.reportFormat);
    quietStandardErrorForGrade(cl); // main() did, before Qt could say a word; tests call this
    BatchReport report(cl.reportPath, format, batchRun(cl));
    // The report on standard output: the summary lines go to stderr, out of its way.
    FILE *const lines = report.toStandardOutput() ? stderr : stdout;
    // A fault of the batch, not of a submission: said on stderr, and in the report where the
    // format can say it (the platforms' files).
    const auto batchError = [&](const QString &error) { return failGrade(cl, error); };

    const ExerciseFile e = readExerciseFile(cl.exercisePath);
    if (!e.error.isEmpty())
        return batchError("--exercise: " + e.error);
    if (!e.ignored.isEmpty())
        printLine(QString("lightbench: --exercise: %1: ignored: %2")
                      .arg(cl.exercisePath, summarisedList(e.ignored, "; ")),
                  stderr);
    const GradingSpec &spec = e.file.exercise->grading;
    report.run().casePoints = pointsPerCase(spec);
    report.run().passShare = spec.passShare;
    report.run().tolerance = spec.tolerance;
    // Time for one submission: its process, its trial and its frames; a hang ends here.
    const int limitMs = gradingTimeLimitMs(spec, int(e.file.exercise->mistakes.size()));

    const QStringList paths = distinctSubmissions(cl.submissions);
    if (describesOneSubmission(format) && paths.size() > 1)
        return batchError(QString("--report-format %1: describes one submission (the platform "
                                  "grades one student per run); %2 were given")
                              .arg(reportFormatNames().value(cl.reportFormat))
                              .arg(paths.size()));
    std::vector<GradedSubmission> rows(std::size_t(paths.size()));
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
    if (const QString error = outputsUnwritable(cl); !error.isEmpty())
        return batchError(error);
    // Two batches writing one report (or one sheet folder) would lose one's rows: while one
    // runs, the other is refused.
    std::vector<std::unique_ptr<QLockFile>> locks;
    const auto lock = [&](const QString &option, const QString &target, const QString &lockPath) {
        return lockOutput(option, target, lockPath, locks);
    };
    if (!cl.reportPath.isEmpty() && cl.reportPath != "-")
        if (const QString error = lock("--report", cl.reportPath, cl.reportPath + ".lock");
            !error.isEmpty())
            return batchError(error);
    if (!cl.sheetsDir.isEmpty())
        if (const QString error =
                lock("--sheets", cl.sheetsDir, sheetListPath(cl.sheetsDir) + ".lock");
            !error.isEmpty())
            return batchError(error);
    // The sheet folder is to hold this run's sheets alone: the list names the last run's and
    // this run's while it goes on, and only a run that finishes removes the last run's it did
    // not write again (a faulty exercise found midway leaves them as they were). A list that
    // cannot be written (a full disk) is said and costs the exit code, not the grading.
    bool sheetListFailed = false;
    QStringList sheets, lastRunSheets;
    if (!cl.sheetsDir.isEmpty()) {
        for (const QString &name : names)
            sheets << QFileInfo(gradingSheetPath(cl.sheetsDir, name)).fileName();
        lastRunSheets = readSheetList(cl.sheetsDir);
        QStringList both = lastRunSheets;
        for (const QString &s : sheets)
            if (!both.contains(s))
                both << s;
        if (const QString error = writeSheetList(cl.sheetsDir, both); !error.isEmpty()) {
            printLine("lightbench: --sheets: " + error, stderr);
            sheetListFailed = true;
        }
    }

    bool anyUnreadable = false;
    std::vector<int> toRun;
    for (int i = 0; i < int(submissions.size()); ++i) {
        GradedSubmission &row = rows[std::size_t(i)];
        row.name = names[i];
        if (!submissions[std::size_t(i)].error.isEmpty()) {
            printLine("lightbench: " + escapedControls(submissions[std::size_t(i)].error), stderr);
            row.report.status = "unreadable";
            row.report.diagnostic = submissions[std::size_t(i)].error;
            finished[std::size_t(i)] = true;
            anyUnreadable = true;
        } else {
            toRun.push_back(i);
        }
    }

    ProgressLine progress(int(rows.size()));
    // Each line is printed once its submission and all before it are done, and the report is
    // written again after each: what finished is kept whenever the batch ends.
    std::size_t printed = 0;
    const auto printFinished = [&](bool all) {
        for (; printed < rows.size(); ++printed) {
            if (finished[printed]) {
                progress.clear();
                printLine(summaryLine(report.run(), rows[printed]), lines);
            } else if (!all) {
                break;
            }
        }
    };
    QString reportError; // the last write's, said once until it changes
    const auto writeReport = [&](bool final) {
        std::vector<GradedSubmission> done;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (finished[i])
                done.push_back(rows[i]);
        const QString error = report.write(done, final);
        if (!error.isEmpty() && error != reportError)
            printLine("lightbench: --report: " + error, stderr);
        reportError = error;
    };
    writeReport(false);
    if (!reportError.isEmpty())
        return 1; // nothing graded yet: no time lost on a batch whose report cannot be kept

    // One process per core (two here, at most four): each submission in a process of its
    // own. LIGHTBENCH_GRADE_PROCESSES sets how many (bench/grade.sh compares).
    const int processes = qEnvironmentVariableIntValue("LIGHTBENCH_GRADE_PROCESSES");
    const int parallel = processes > 0 ? std::min(processes, 16)
                                       : std::max(1, std::min(QThread::idealThreadCount(), 4));
    // The batch's frames (below): the folder outlives every child, declared before them.
    const int mistakes = int(e.file.exercise->mistakes.size());
    removeAbandonedFramesFolders(); // batches killed before they could, first: their space counts
    std::unique_ptr<FramesFolder> framesDir;
    if (preparationWorthIt(spec, mistakes, toRun.size(), parallel))
        framesDir = std::make_unique<FramesFolder>();
    QEventLoop loop;
    QObject children; // owns the processes: each goes with it, whatever the loop left undone
    StopSignals stop;
    int stoppedBy = 0;
    std::size_t next = 0;
    int running = 0;
    QString batchFailure; // the exercise's fault, said by a child: no more are started
    QElapsedTimer clock;
    clock.start();
    std::vector<qint64> startedAt(rows.size(), 0);
    progress.show(int(std::count(finished.begin(), finished.end(), true)));
    QTimer ticks; // the progress line's clock moves while nothing finishes
    QObject::connect(&ticks, &QTimer::timeout, &loop, [&] {
        progress.show(int(std::count(finished.begin(), finished.end(), true)));
    });
    ticks.start(1000);
    std::function<void()> startMore;
    // The reference's and the mistakes' frames, drawn once for the batch by a child of their
    // own before the submissions' (grade_frames.h); without them each child draws its own.
    QString frames;
    bool preparing = framesDir && framesDir->isValid();
    const auto prepare = [&] {
        QProcess *p = boundedChild(&children, preparationTimeLimitMs(spec, mistakes));
        QObject::connect(
            p, &QProcess::finished, &loop,
            [&, p](int exitCode, QProcess::ExitStatus status) {
                if (preparedFrames(*p, exitCode, status))
                    frames = framesDir->path();
                else
                    framesDir->remove(); // what it wrote goes now, not at the batch's end
                p->deleteLater();
                preparing = false;
                startMore();
            },
            Qt::QueuedConnection);
        startPreparation(*p, cl, framesDir->path());
    };
    const auto ended = [&](int i, QProcess *p) {
        GradedSubmission &row = rows[std::size_t(i)];
        row.seconds = double(clock.elapsed() - startedAt[std::size_t(i)]) / 1000.0;
        GradingReport &result = row.report;
        const std::optional<GradingReport> said = readGradingReport(p->readAllStandardOutput());
        p->deleteLater();
        --running;
        // A child that ended without a report while the batch is being stopped was stopped
        // with it (Ctrl+C reaches the whole process group): it did not finish.
        const bool stopped = StopSignals::received() && !said;
        if (stopped) {
        } else if (result.status == "timed out") {
            result.diagnostic = QString("more than %1 s").arg(limitMs / 1000.0, 0, 'f', 1);
        } else if (said) { // a result printed counts, whatever came after it
            result = *said;
            if (kBatchFailures.contains(result.status) && batchFailure.isEmpty())
                batchFailure = result.status + ": " + result.diagnostic.section('\n', 0, 0);
        } else {
            result.status = "crashed";
            const QString line = QString::fromUtf8(p->readAllStandardError())
                                     .split('\n')
                                     .filter("lightbench")
                                     .value(0)
                                     .trimmed();
            result.diagnostic = (p->error() == QProcess::FailedToStart ? "could not start: " : "") +
                                endedWithoutReport(*p);
            if (!line.isEmpty())
                result.diagnostic += "; " + line;
        }
        if (!stopped && batchFailure.isEmpty()) {
            finished[std::size_t(i)] = true;
            printFinished(false);
            writeReport(false);
            progress.show(int(std::count(finished.begin(), finished.end(), true)));
        }
        startMore(); // or the end, when nothing is left to start and nothing runs
    };
    startMore = [&] {
        if (preparing)
            return; // its end starts the submissions
        while (running < parallel && next < toRun.size() && batchFailure.isEmpty() &&
               !StopSignals::received()) {
            const int i = toRun[next++];
            QProcess *p = boundedChild(&children, limitMs, [&rows, i](QProcess *) {
                rows[std::size_t(i)].report.status = "timed out";
            });
            QStringList args{
                "--grade-one", paths[i],        "--grade-name", names[i],
                "--exercise",  cl.exercisePath, "--seed",       QString::number(cl.seed)};
            if (!cl.sheetsDir.isEmpty())
                args << "--sheets" << cl.sheetsDir;
            if (!frames.isEmpty())
                args << "--grade-frames" << frames;
            // Queued: a process that fails to start says so from inside start(), before
            // the loop runs.
            QObject::connect(
                p, &QProcess::finished, &loop, [&, i, p] { ended(i, p); }, Qt::QueuedConnection);
            ++running;
            startedAt[std::size_t(i)] = clock.elapsed();
            // LIGHTBENCH_GRADE_PROGRAM stands in for this program in the children (the tests
            // give one that crashes, chatters or is not there).
            p->start(gradingChildProgram(), args);
        }
        if (running == 0) // a batch failure or a stop with nothing left running
            loop.quit();
    };
    QObject::connect(&stop, &StopSignals::stopRequested, &loop, [&](int signal) {
        stoppedBy = signal;
        loop.quit();
    });
    if (!toRun.empty()) {
        QTimer::singleShot(0, &loop, preparing ? std::function<void()>(prepare) : startMore);
        // (from inside the loop, so that its quit counts)
        loop.exec();
    }
    ticks.stop();
    progress.clear();
    stoppedBy = StopSignals::received(); // also one that came while the loop was ending
    if (stoppedBy) {
        // No child is left running: each is killed and waited for before the batch ends.
        for (QProcess *p : children.findChildren<QProcess *>()) {
            p->disconnect();
            p->kill();
            p->waitForFinished(5000);
        }
        printFinished(true);
        writeReport(true);
        const int done = int(std::count(finished.begin(), finished.end(), true));
        printLine(QString("lightbench: --grade: stopped by %1 with %2 of %3 submissions done%4")
                      .arg(signalName(stoppedBy))
                      .arg(done)
                      .arg(rows.size())
                      .arg(!report.wanted() ? QString()
                           : report.toStandardOutput()
                               ? QString("; standard output holds their rows")
                               : QString("; %1 holds their rows").arg(cl.reportPath)),
                  stderr);
        return StopSignals::exitCodeFor(stoppedBy);
    }
    if (!batchFailure.isEmpty())
        return batchError(QString("--exercise: %1: %2").arg(cl.exercisePath, batchFailure));
    printFinished(true);
    writeReport(true);
    if (!cl.sheetsDir.isEmpty() && !sheetListFailed) {
        // Written this run, or failed to be (the old file stays): by file name.
        QStringList written, failed;
        for (const GradedSubmission &g : rows) {
            if (!g.report.sheet.isEmpty())
                written << QFileInfo(g.report.sheet).fileName();
            else if (!g.report.sheetError.isEmpty())
                failed << QFileInfo(gradingSheetPath(cl.sheetsDir, g.name)).fileName();
        }
        if (const QString error = finishSheetList(cl.sheetsDir, lastRunSheets, written, failed);
            !error.isEmpty()) {
            printLine("lightbench: --sheets: " + error, stderr);
            sheetListFailed = true;
        }
    }
    const bool sheetFailed = std::any_of(rows.begin(), rows.end(), [](const GradedSubmission &g) {
        return g.report.graded() && !g.report.sheetError.isEmpty();
    });
    if (!reportError.isEmpty() || sheetFailed || sheetListFailed)
        return 1; // each line said which file and why
    if (anyUnreadable)
        return 2;
    // GitHub Classroom: the job fails unless the submission passed every case.
    const bool allPassed = std::all_of(rows.begin(), rows.end(), [](const GradedSubmission &g) {
        return g.report.graded() && g.report.passedCount() == int(g.report.cases.size());
    });
    return format == ReportFormat::GitHub && !allPassed ? 3 : 0;
}

} // namespace lb
