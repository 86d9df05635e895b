#include "grade_outputs.h"

#include "bounded_read.h"
#include "grading_progress.h"
#include "qt_paths.h"
#include "safe_write.h"
#include "standard_output.h"
#include "terminal.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace lb {

namespace {

// Far more names than any class: the list is read before the batch, and a list gone wrong
// must not cost time or memory.
constexpr qint64 kMaxSheetListBytes = 4 << 20;
const char *const kSheetListName = ".lightbench-sheets";

bool isOwnSheetName(const QString &name)
{
    // ':' too: on Windows "C:x.png" is relative to a drive and "x:y.png" a file's stream.
    return name.endsWith(QLatin1String(".png")) && name.size() > 4 && !name.contains('/') &&
           !name.contains('\\') && !name.contains(':') && !name.contains(QChar(0));
}

} // namespace

BatchReport::BatchReport(const QString &path, ReportFormat format, const GradingRun &run)
    : m_path(path), m_format(format), m_run(run)
{
}

QString BatchReport::write(const std::vector<GradedSubmission> &rows, bool final)
{
    if (!wanted())
        return {};
    const QByteArray bytes = reportBytes(m_format, m_run, rows);
    if (!toStandardOutput())
        return writeFileSafely(m_path, bytes);
    if (!final) // a stream cannot be rewritten: it gets the whole report once
        return {};
    return writeStandardOutput(bytes);
}

void BatchReport::writeBatchError(const QString &error)
{
    if (!wanted() || !describesOneSubmission(m_format))
        return;
    m_run.error = error;
    write({}, true); // its own failure cannot be said better than the error itself
}

ProgressLine::ProgressLine(int total) : m_terminal(platform::isTerminal(stderr)), m_total(total)
{
    m_clock.start();
}

void ProgressLine::show(int done)
{
    m_done = done;
    if (!m_terminal)
        return;
    const QByteArray text = progressText(done, m_total, m_clock.elapsed()).toUtf8();
    // Spaces over what a longer line before left; the cursor stays at its start.
    const int pad = std::max(0, m_width - int(text.size()));
    std::fprintf(stderr, "\r%s%*s\r", text.constData(), pad, "");
    std::fflush(stderr);
    m_width = int(text.size());
    m_shown = true;
}

void ProgressLine::clear()
{
    if (!m_shown)
        return;
    std::fprintf(stderr, "\r%*s\r", m_width, "");
    std::fflush(stderr);
    m_shown = false;
    m_width = 0;
}

QString sheetListPath(const QString &dir)
{
    return QDir(dir).filePath(QLatin1String(kSheetListName));
}

QStringList readSheetList(const QString &dir)
{
    QStringList names;
    const QString listPath = sheetListPath(dir);
    if (!QFileInfo::exists(listPath))
        return names;
    // A list that cannot be read (too big, no file) names nothing.
    const BoundedRead read = readBounded(listPath, FileLimit{"a sheet list", kMaxSheetListBytes});
    for (const QJsonValue &v : QJsonDocument::fromJson(read.bytes).object()["sheets"].toArray())
        if (const QString name = v.toString(); isOwnSheetName(name) && !names.contains(name))
            names << name;
    return names;
}

QString writeSheetList(const QString &dir, const QStringList &names)
{
    QJsonArray list;
    for (const QString &name : names)
        list.append(name);
    return writeFileSafely(sheetListPath(dir),
                           QJsonDocument(QJsonObject{{"sheets", list}}).toJson());
}

void removeSheets(const QString &dir, const QStringList &names)
{
    for (const QString &name : names) {
        if (!isOwnSheetName(name))
            continue;
        const QFileInfo sheet(QDir(dir).filePath(name));
        if (sheet.isFile() && !sheet.isSymLink())
            QFile::remove(sheet.filePath());
    }
}

QString finishSheetList(const QString &dir, const QStringList &lastRun, const QStringList &written,
                        const QStringList &failed)
{
    const auto key = [](const QString &name) {
        return name.normalized(QString::NormalizationForm_C).toCaseFolded();
    };
    const auto among = [&](const QString &name, const QStringList &names) {
        return std::any_of(names.begin(), names.end(),
                           [&](const QString &n) { return key(n) == key(name); });
    };
    // A last-run sheet written again under another case (Alice.png, now alice.png) is the same
    // file where names are folded (macOS, Windows): kept; where they are not, it is a sheet of
    // its own that nothing else would ever clean up: stale.
    const auto sameFile = [&](const QString &a, const QString &b) {
        std::error_code error;
        return std::filesystem::equivalent(platform::nativePath(QDir(dir).filePath(a)),
                                           platform::nativePath(QDir(dir).filePath(b)), error);
    };
    QStringList stale, listed = written;
    for (const QString &name : lastRun) {
        if (among(name, failed)) {
            listed << name;
        } else if (!written.contains(name)) {
            const auto again = std::find_if(written.begin(), written.end(),
                                            [&](const QString &n) { return key(n) == key(name); });
            if (again == written.end() || !sameFile(name, *again))
                stale << name;
        }
    }
    removeSheets(dir, stale);
    return writeSheetList(dir, listed);
}

} // namespace lb
