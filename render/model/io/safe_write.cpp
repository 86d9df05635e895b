#include "safe_write.h"

#include "exclusive_file.h"
#include "message_text.h"
#include "png_encoder.h"
#include "qt_paths.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>
#include <QRandomGenerator>

#include <filesystem>
#include <memory>
#include <mutex>

namespace lb {

namespace {

// The translation context of this file's messages.
struct SafeWriteMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::SafeWrite)
};

// Where the bytes go: the file at the end of the target's symbolic links (the links stay
// links), or why there is none that may be replaced.
struct Target
{
    QString path; // resolved
    bool exists = false;
    unsigned permissions = 0; // the old file's, kept by the new one
    QString error;            // "GIVEN: why"
};

// `tryCreating`: a file is also made (and removed) in the folder, for the checks before a long
// run, where permission alone misleads (root "may" write /proc).
Target resolveTarget(const QString &given, bool tryCreating = false)
{
    using platform::FileError;
    using platform::FileKind;
    Target t;
    QString path = given;
    const auto fail = [&](const QString &why) {
        t.error = QString("%1: %2").arg(echoedPath(given), why);
        return t;
    };
    // As the kernel counts: more links than this in a row is a loop.
    for (int links = 0; links <= 40; ++links) {
        const platform::FileStatus st =
            platform::fileStatus(platform::nativePath(path), platform::Links::Keep);
        if (st.error.code == FileError::Loop)
            return fail(SafeWriteMessages::tr("a loop of symbolic links"));
        if (st.error.code == FileError::Missing)
            break; // a new file
        if (st.error)
            return fail(platform::errorText(st.error));
        if (st.kind == FileKind::Link) {
            FileError error;
            const std::filesystem::path link =
                platform::linkTarget(platform::nativePath(path), error);
            if (error)
                return fail(platform::errorText(error));
            path = QDir(QFileInfo(path).absolutePath())
                       .absoluteFilePath(platform::fromNativePath(link));
            if (links == 40)
                return fail(SafeWriteMessages::tr("a loop of symbolic links"));
            continue;
        }
        if (st.kind != FileKind::Regular)
            return fail(SafeWriteMessages::tr(
                "not a regular file (a device, a pipe or a folder); not replaced"));
        // A read-only file is not replaced, as cp and QSaveFile refuse it: the rename would
        // (only the folder's permissions count for it). Read-only: no write bit for its owner
        // when that is us, or none at all (root, for whom the bits do not bind, too).
        if ((st.ownedByThisUser && !(st.permissions & 0200)) || !(st.permissions & 0222))
            return fail(SafeWriteMessages::tr("read-only (mode %1); not replaced")
                            .arg(st.permissions & 0777, 4, 8, QChar('0')));
        t.exists = true;
        t.permissions = st.permissions;
        break;
    }
    // The temporary file is made in the target's folder, so that folder must take one.
    const QString folder = QFileInfo(path).absolutePath();
    const platform::FileStatus st =
        platform::fileStatus(platform::nativePath(folder), platform::Links::Follow);
    if (st.error)
        return fail(
            st.error.code == FileError::Missing
                ? SafeWriteMessages::tr("the folder %1 does not exist").arg(echoedPath(folder))
                : QString("%1: %2").arg(echoedPath(folder), platform::errorText(st.error)));
    if (st.kind != FileKind::Folder)
        return fail(SafeWriteMessages::tr("%1 is not a folder").arg(echoedPath(folder)));
    FileError refused = platform::creatingFilesRefused(platform::nativePath(folder));
    if (!refused && tryCreating)
        refused = platform::fileCreationFails(platform::nativePath(folder));
    if (refused)
        return fail(SafeWriteMessages::tr("cannot write in %1: %2")
                        .arg(echoedPath(folder), platform::errorText(refused)));
    t.path = path;
    return t;
}

// One file on its way: its temporary, written and flushed, waiting for its rename.
class PendingFile
{
public:
    explicit PendingFile(Target target) : m_target(std::move(target)) {}

    // Writes `bytes` to a new temporary file beside the target; empty or why not.
    QString write(const QByteArray &bytes)
    {
        if (const platform::FileError error = open())
            return failed(error);
        if (m_target.exists) // the permissions the old file had, not the umask's
            m_file.keepPermissions(m_target.permissions);
        if (const platform::FileError error =
                m_file.writeAll(bytes.constData(), std::size_t(bytes.size())))
            return failed(error);
        if (const platform::FileError error = m_file.finish())
            return failed(error);
        return {};
    }

    // Puts the written temporary in the target's place; empty or why not.
    QString commit()
    {
        if (const platform::FileError error = m_file.commitOver(m_target.path))
            return failed(error);
        return {};
    }

private:
    platform::FileError open()
    {
        const QString base = QFileInfo(m_target.path).fileName();
        const QString folder = QFileInfo(m_target.path).absolutePath();
        platform::FileError error;
        for (int attempt = 0; attempt < 100; ++attempt) {
            // At most 214 bytes whatever the target's name: "." 200 "." 8 ".tmp".
            const QString name =
                "." + leftInBytes(base, 200) + "." +
                QString("%1").arg(QRandomGenerator::global()->generate(), 8, 16, QLatin1Char('0')) +
                ".tmp";
            error = m_file.create(QDir(folder).filePath(name));
            if (error.code != platform::FileError::Exists)
                break;
        }
        return error;
    }

    QString failed(const platform::FileError &error)
    {
        m_file.discard();
        return QString("%1: %2").arg(echoedPath(m_target.path), platform::errorText(error));
    }

    Target m_target;
    platform::ExclusiveFile m_file; // removed as this goes, unless committed
};

} // namespace

void reportFileSizeLimitAsError()
{
    static std::once_flag once;
    std::call_once(once, [] { platform::reportFileSizeLimitAsError(); });
}

QString leftInBytes(const QString &name, int maxBytes)
{
    qsizetype end = 0;
    int bytes = 0;
    while (end < name.size()) {
        const qsizetype length =
            name[end].isHighSurrogate() && end + 1 < name.size() && name[end + 1].isLowSurrogate()
                ? 2
                : 1;
        const int more = int(QFile::encodeName(name.mid(end, length)).size());
        if (bytes + more > maxBytes)
            break;
        bytes += more;
        end += length;
    }
    return name.left(end);
}

QString unwritableTarget(const QString &path)
{
    return resolveTarget(path, true).error;
}

QString writeFilesSafely(const std::vector<std::pair<QString, QByteArray>> &files)
{
    reportFileSizeLimitAsError();
    std::vector<std::unique_ptr<PendingFile>> pending;
    for (const auto &[path, bytes] : files) {
        Target target = resolveTarget(path);
        if (!target.error.isEmpty())
            return target.error;
        pending.push_back(std::make_unique<PendingFile>(std::move(target)));
    }
    for (std::size_t i = 0; i < files.size(); ++i)
        if (const QString error = pending[i]->write(files[i].second); !error.isEmpty())
            return error; // every temporary is removed as `pending` goes
    for (const std::unique_ptr<PendingFile> &file : pending)
        if (const QString error = file->commit(); !error.isEmpty())
            return error;
    return {};
}

QString writeFileSafely(const QString &path, const QByteArray &bytes)
{
    return writeFilesSafely({{path, bytes}});
}

QString writeImageSafely(const QString &path, const QImage &image, int quality)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix.isEmpty() || suffix == "png") {
        const QByteArray bytes = encodePng(image, pngLevelForQuality(quality));
        if (bytes.isEmpty())
            return QString("%1: %2").arg(
                echoedPath(path), image.isNull()
                                      ? SafeWriteMessages::tr("no image to write")
                                      : SafeWriteMessages::tr("the PNG could not be encoded"));
        return writeFileSafely(path, bytes);
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, suffix.toLatin1());
    writer.setQuality(quality);
    if (!writer.write(image))
        return QString("%1: %2").arg(echoedPath(path), writer.errorString());
    return writeFileSafely(path, bytes);
}

} // namespace lb
