#include "bounded_read.h"

#include "message_text.h"
#include "qt_paths.h"
#include "safe_write.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace lb {

namespace {

// The translation context of this file's messages.
struct BoundedReadMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::BoundedRead)
};

// A kind of file, or what is saved, as FileLimit marks it.
QString noun(const char *phrase)
{
    return QCoreApplication::translate("lb::FileLimit", phrase);
}

} // namespace

QString missingFileReason(const QString &path)
{
    using platform::FileError;
    const platform::FileStatus st =
        platform::fileStatus(platform::nativePath(path), platform::Links::Follow);
    if (!st.error)
        return BoundedReadMessages::tr("no such file"); // it came meanwhile; say what was seen
    if (st.error.code == FileError::Loop)
        return BoundedReadMessages::tr("a loop of symbolic links");
    if (st.error.code == FileError::Missing && QFileInfo(path).isSymLink())
        return BoundedReadMessages::tr("a symbolic link to %1, which does not exist")
            .arg(echoedPath(QFileInfo(path).symLinkTarget()));
    return st.error.code == FileError::Missing ? BoundedReadMessages::tr("no such file")
                                               : platform::errorText(st.error);
}

QString sizeForMessage(qint64 bytes)
{
    // Rounded up: a file one byte over a 1024 KiB limit reads as 1025 KiB, not as the limit.
    const bool mega = bytes >= 10ll << 20;
    const qint64 unit = mega ? 1ll << 20 : 1ll << 10;
    return (mega ? BoundedReadMessages::tr("%1 MB") : BoundedReadMessages::tr("%1 KiB"))
        .arg((bytes + unit - 1) / unit);
}

static QString limitText(const FileLimit &limit)
{
    const QString size = sizeForMessage(limit.bytes);
    //: a file's size limit (%1, "64 MB") and where it comes from (%2, "the import memory limit")
    return limit.why ? BoundedReadMessages::tr("%1, %2").arg(size, noun(limit.why)) : size;
}

QString unreadableFile(const QString &path, const FileLimit &limit)
{
    const QFileInfo info(path);
    if (!info.exists())
        return QString("%1: %2").arg(echoedPath(path), missingFileReason(path));
    if (!info.isFile())
        return BoundedReadMessages::tr("%1: not a regular file (a folder, a device or a pipe)")
            .arg(echoedPath(path));
    if (info.size() > limit.bytes)
        //: %1 a path, %2 its size, %3 a kind of file ("a scene file"), %4 the limit ("64 MB")
        return BoundedReadMessages::tr("%1: %2 is more than %3 may be (%4)")
            .arg(echoedPath(path), sizeForMessage(info.size()), noun(limit.kind), limitText(limit));
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
        r.error = QString("%1: %2").arg(echoedPath(path), f.errorString());
        return r;
    }
    r.bytes = f.read(limit.bytes + 1);
    if (r.bytes.size() > limit.bytes) { // it grew since the check
        r.bytes.clear();
        //: %1 a path, %2 a kind of file ("a scene file"), %3 the limit ("64 MB")
        r.error = BoundedReadMessages::tr("%1: more than %2 may be (%3)")
                      .arg(echoedPath(path), noun(limit.kind), limitText(limit));
    }
    return r;
}

QString writeWithinLimit(const QString &path, const QByteArray &bytes, const char *what,
                         const FileLimit &limit)
{
    if (bytes.size() > limit.bytes)
        //: %1 a path, %2 what is saved ("the scene"), %3 its size, %4 a kind of file ("a scene
        //: file"), %5 the limit ("64 MB")
        return BoundedReadMessages::tr(
                   "%1: not saved: %2 would take %3, more than %4 may be (%5), so it could not be "
                   "opened again")
            .arg(echoedPath(path), noun(what), sizeForMessage(bytes.size()), noun(limit.kind),
                 sizeForMessage(limit.bytes));
    return writeFileSafely(path, bytes);
}

} // namespace lb
