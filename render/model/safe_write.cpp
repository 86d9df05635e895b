#include "safe_write.h"

#include "message_text.h"
#include "png_encoder.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>
#include <QRandomGenerator>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

namespace lb {

namespace {

// The translation context of this file's messages.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(lb::SafeWrite)
};

// A path as a message shows it: a 60 MB name is cut short.
QString shown(const QString &path)
{
    return echoedValue(path, 300);
}

QString systemReason(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

// Where the bytes go: the file at the end of the target's symbolic links (the links stay
// links), or why there is none that may be replaced.
struct Target
{
    QString path; // resolved
    bool exists = false;
    mode_t mode = 0; // the old file's permissions, kept by the new one
    QString error;   // "GIVEN: why"
};

Target resolveTarget(const QString &given)
{
    Target t;
    QString path = given;
    const auto fail = [&](const QString &why) {
        t.error = QString("%1: %2").arg(shown(given), why);
        return t;
    };
    // As the kernel counts: more links than this in a row is a loop.
    for (int links = 0; links <= 40; ++links) {
        const QByteArray native = QFile::encodeName(path);
        struct stat st;
        if (::lstat(native.constData(), &st) != 0) {
            if (errno == ELOOP)
                return fail(Text::tr("a loop of symbolic links"));
            if (errno != ENOENT)
                return fail(systemReason(errno));
            break; // a new file
        }
        if (S_ISLNK(st.st_mode)) {
            QByteArray link(PATH_MAX, '\0');
            const ssize_t n = ::readlink(native.constData(), link.data(), std::size_t(link.size()));
            if (n < 0)
                return fail(systemReason(errno));
            link.truncate(int(n));
            path = QDir(QFileInfo(path).absolutePath()).absoluteFilePath(QFile::decodeName(link));
            if (links == 40)
                return fail(Text::tr("a loop of symbolic links"));
            continue;
        }
        if (!S_ISREG(st.st_mode))
            return fail(
                Text::tr("not a regular file (a device, a pipe or a folder); not replaced"));
        t.exists = true;
        t.mode = st.st_mode & 07777;
        break;
    }
    // The temporary file is made in the target's folder, so that folder must take one.
    const QString folder = QFileInfo(path).absolutePath();
    const QByteArray nativeFolder = QFile::encodeName(folder);
    struct stat st;
    if (::stat(nativeFolder.constData(), &st) != 0)
        return fail(errno == ENOENT ? Text::tr("the folder %1 does not exist").arg(shown(folder))
                                    : QString("%1: %2").arg(shown(folder), systemReason(errno)));
    if (!S_ISDIR(st.st_mode))
        return fail(Text::tr("%1 is not a folder").arg(shown(folder)));
    if (::access(nativeFolder.constData(), W_OK | X_OK) != 0)
        return fail(Text::tr("cannot write in %1: %2").arg(shown(folder), systemReason(errno)));
    t.path = path;
    return t;
}

// One file on its way: its temporary, written and flushed, waiting for its rename.
class PendingFile
{
public:
    explicit PendingFile(Target target) : m_target(std::move(target)) {}
    PendingFile(const PendingFile &) = delete;
    PendingFile &operator=(const PendingFile &) = delete;
    ~PendingFile() { discard(); }

    // Writes `bytes` to a new temporary file beside the target; empty or why not.
    QString write(const QByteArray &bytes)
    {
        if (!open())
            return failed(errno);
        if (m_target.exists) // the permissions the old file had, not the umask's
            ::fchmod(m_fd, m_target.mode);
        for (qint64 done = 0; done < bytes.size();) {
            const ssize_t n =
                ::write(m_fd, bytes.constData() + done, std::size_t(bytes.size() - done));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return failed(n < 0 ? errno : ENOSPC);
            done += n;
        }
        // Some file systems report a full disk or a quota only here (NFS) or at close.
        if (::fsync(m_fd) != 0 && errno != EINVAL && errno != EROFS)
            return failed(errno);
        const int fd = std::exchange(m_fd, -1);
        if (::close(fd) != 0 && errno != EINTR)
            return failed(errno);
        return {};
    }

    // Puts the written temporary in the target's place; empty or why not.
    QString commit()
    {
        if (::rename(m_temp.constData(), QFile::encodeName(m_target.path).constData()) != 0)
            return failed(errno);
        m_temp.clear();
        return {};
    }

private:
    bool open()
    {
        const QString base = QFileInfo(m_target.path).fileName();
        const QString folder = QFileInfo(m_target.path).absolutePath();
        for (int attempt = 0; attempt < 100; ++attempt) {
            const QString name =
                QString(".%1.%2.tmp")
                    .arg(base.left(200))
                    .arg(QRandomGenerator::global()->generate(), 8, 16, QLatin1Char('0'));
            m_temp = QFile::encodeName(QDir(folder).filePath(name));
            // 0666 less the umask, as any new file; O_EXCL: never someone else's file.
            m_fd = ::open(m_temp.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (m_fd >= 0)
                return true;
            if (errno != EEXIST) {
                m_temp.clear();
                return false;
            }
        }
        m_temp.clear();
        return false;
    }

    QString failed(int error)
    {
        discard();
        return QString("%1: %2").arg(shown(m_target.path), systemReason(error));
    }

    void discard()
    {
        if (m_fd >= 0)
            ::close(std::exchange(m_fd, -1));
        if (!m_temp.isEmpty())
            ::unlink(m_temp.constData());
        m_temp.clear();
    }

    Target m_target;
    QByteArray m_temp; // the temporary's path while it exists
    int m_fd = -1;
};

} // namespace

void reportFileSizeLimitAsError()
{
    static std::once_flag once;
    std::call_once(once, [] { std::signal(SIGXFSZ, SIG_IGN); });
}

QString unwritableTarget(const QString &path)
{
    return resolveTarget(path).error;
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
            return QString("%1: %2").arg(shown(path),
                                         image.isNull() ? Text::tr("no image to write")
                                                        : Text::tr("the PNG could not be encoded"));
        return writeFileSafely(path, bytes);
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, suffix.toLatin1());
    writer.setQuality(quality);
    if (!writer.write(image))
        return QString("%1: %2").arg(shown(path), writer.errorString());
    return writeFileSafely(path, bytes);
}

} // namespace lb
