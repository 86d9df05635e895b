#include "bounded_read.h"

#include "message_text.h"
#include "safe_write.h"

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace lb {

namespace {

QString shown(const QString &path)
{
    return echoedValue(path, 300);
}

} // namespace

QString missingFileReason(const QString &path)
{
    struct stat st;
    if (::stat(QFile::encodeName(path).constData(), &st) == 0)
        return "no such file"; // it came meanwhile; say what was seen
    if (errno == ELOOP)
        return "a loop of symbolic links";
    if (errno == ENOENT && QFileInfo(path).isSymLink())
        return QString("a symbolic link to %1, which does not exist")
            .arg(shown(QFileInfo(path).symLinkTarget()));
    return errno == ENOENT ? QString("no such file") : QString::fromLocal8Bit(std::strerror(errno));
}

QString sizeForMessage(qint64 bytes)
{
    // Rounded up: a file one byte over a 1024 KiB limit reads as 1025 KiB, not as the limit.
    const bool mega = bytes >= 10ll << 20;
    const qint64 unit = mega ? 1ll << 20 : 1ll << 10;
    return QString::number((bytes + unit - 1) / unit) + (mega ? " MB" : " KiB");
}

static QString limitText(const FileLimit &limit)
{
    const QString size = sizeForMessage(limit.bytes);
    return limit.why ? size + ", " + QString::fromLatin1(limit.why) : size;
}

QString unreadableFile(const QString &path, const FileLimit &limit)
{
    const QFileInfo info(path);
    if (!info.exists())
        return QString("%1: %2").arg(shown(path), missingFileReason(path));
    if (!info.isFile())
        return QString("%1: not a regular file (a folder, a device or a pipe)").arg(shown(path));
    if (info.size() > limit.bytes)
        return QString("%1: %2 is more than %3 may be (%4)")
            .arg(shown(path), sizeForMessage(info.size()), QString::fromLatin1(limit.kind),
                 limitText(limit));
    return {};
}

BoundedRead readBounded(const QString &path, const FileLimit &limit)
{
    BoundedRead r;
    r.error = unreadableFile(path, limit);
    if (!r.error.isEmpty())
        return r;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        r.error = QString("%1: %2").arg(shown(path), f.errorString());
        return r;
    }
    r.bytes = f.read(limit.bytes + 1);
    if (r.bytes.size() > limit.bytes) { // it grew since the check
        r.bytes.clear();
        r.error = QString("%1: more than %2 may be (%3)")
                      .arg(shown(path), QString::fromLatin1(limit.kind), limitText(limit));
    }
    return r;
}

QString writeWithinLimit(const QString &path, const QByteArray &bytes, const char *what,
                         const FileLimit &limit)
{
    if (bytes.size() > limit.bytes)
        return QString("%1: not saved: %2 would take %3, more than %4 may be (%5), so it could "
                       "not be opened again")
            .arg(echoedValue(path, 300), what, sizeForMessage(bytes.size()), limit.kind,
                 sizeForMessage(limit.bytes));
    return writeFileSafely(path, bytes);
}

} // namespace lb
