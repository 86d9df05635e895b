#pragma once
// Where a grading batch's results go (grade.h): the report, in its format, to a file written
// again whole after each submission or to standard output once at the end; the progress line
// on a terminal; the sheet folder's list of the sheets this run writes there.

#include "grading_formats.h"

#include <QElapsedTimer>
#include <QString>
#include <QStringList>

#include <cstdio>
#include <vector>

namespace lb {

// The report of --report FILE (or "-") in its format.
class BatchReport
{
public:
    BatchReport(const QString &path, ReportFormat format, const GradingRun &run);
    bool wanted() const { return !m_path.isEmpty(); }
    bool toStandardOutput() const { return m_path == QLatin1String("-"); }
    ReportFormat format() const { return m_format; }
    GradingRun &run() { return m_run; }
    // The rows so far, written whole: to the file after each submission ("" or "PATH: why");
    // standard output only takes the report once, with `final`.
    QString write(const std::vector<GradedSubmission> &rows, bool final);
    // Why nobody was graded, in the report of a format that can say it (the platforms' files:
    // CodeRunner shows no stderr); a CSV or JUnit report is left as it is.
    void writeBatchError(const QString &error);

private:
    QString m_path;
    ReportFormat m_format;
    GradingRun m_run;
};

// "graded 3/30, 0:12 elapsed, about 1:48 left" on stderr, rewritten in place, only when
// stderr is a terminal; cleared before each line the batch prints.
class ProgressLine
{
public:
    explicit ProgressLine(int total);
    void show(int done);
    void clear();

private:
    bool m_shown = false, m_terminal = false;
    int m_total = 0, m_done = 0, m_width = 0;
    QElapsedTimer m_clock;
};

// DIR/.lightbench-sheets: the sheets --grade wrote into DIR (a JSON list of file names: any
// name a submission has fits), so that a run that finishes removes the last run's that it did
// not write again, and the folder holds that run's sheets alone. While a run goes on, the list
// names the last run's and this one's: a run stopped or failed midway leaves every sheet as it
// was, and the next run that finishes still knows them.
QString sheetListPath(const QString &dir);
// The names the folder's list gives that are plain file names ending in .png (no folder part,
// no drive or stream): any other entry is left out.
QStringList readSheetList(const QString &dir);
// "" or "PATH: why".
QString writeSheetList(const QString &dir, const QStringList &names);
// Removes those of `names` that are such names and regular files in `dir` itself (no symbolic
// link): nothing else is ever deleted.
void removeSheets(const QString &dir, const QStringList &names);
// At the end of a run that finished: removes the last run's sheets (`lastRun`, from the list)
// that this run did not write again (`written`) nor failed to write (`failed`: the old file
// stays, as every file a write fails on does), a submission not graded this time among them;
// then lists what is ours. Names are told apart as a case-insensitive, normalising file system
// would (macOS, Windows): "Ana.png" is never removed as stale beside this run's "ana.png".
// "" or "PATH: why".
QString finishSheetList(const QString &dir, const QStringList &lastRun, const QStringList &written,
                        const QStringList &failed);

} // namespace lb
