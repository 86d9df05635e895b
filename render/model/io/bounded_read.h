#pragma once
// Every file the user names (shaders, scenes, textures, meshes) is checked before a byte of it
// is read: /dev/zero, a FIFO or a folder is no file, and a file over its kind's limit is
// refused by its size instead of being read until memory runs out. Messages name the path
// (elided when absurdly long), what is wrong, and the limit.

#include <QByteArray>
#include <QString>

namespace lb {

// `kind` and `why` are English noun phrases marked where they are written with
// QT_TRANSLATE_NOOP("lb::FileLimit", ...): the messages translate them in that context.
struct FileLimit
{
    const char *kind; // "a shader", "a scene file", ...: "2048 KiB is more than a shader may be"
    qint64 bytes;
    const char *why = nullptr; // after the limit: "(2048 MB, the import memory limit)"
};

// Empty when `path` is a regular file within the limit, else "PATH: why".
QString unreadableFile(const QString &path, const FileLimit &limit);

struct BoundedRead
{
    QByteArray bytes;
    QString error; // "PATH: why"; empty when `bytes` is the file
};

// Checks first, then reads at most limit + 1 bytes (a file that grew meanwhile is refused).
BoundedRead readBounded(const QString &path, const FileLimit &limit);

// Writes `bytes` safely (safe_write.h), unless they are more than `limit` allows, which
// readBounded() would refuse: "PATH: not saved: the scene would take 70 MB, more than a scene
// file may be (64 MB), so it could not be opened again". `what`: "the scene", "the lesson",
// marked as `kind` is.
QString writeWithinLimit(const QString &path, const QByteArray &bytes, const char *what,
                         const FileLimit &limit);
// Why `path` is not there: "no such file", "a loop of symbolic links", "a symbolic link to
// TARGET, which does not exist", or the system's reason ("Permission denied").
QString missingFileReason(const QString &path);

// "2.5 MB", "640 KiB": a size as a message says it.
QString sizeForMessage(qint64 bytes);

} // namespace lb
