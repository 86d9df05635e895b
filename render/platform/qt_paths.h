#pragma once
// Qt's side of the file system's answers (file_status.h, which the import helper uses without
// Qt): a QString path as the system's calls take it and back, and the system's words as a
// QString.

#include "file_status.h"

#include <QFile>
#include <QString>

namespace lb::platform {

// The system's words for `error`, as a message shows them.
inline QString errorText(const FileError &error)
{
    return QString::fromLocal8Bit(error.reason.c_str());
}

// A Qt path as the system's calls take it: the bytes QFile would hand them, so that a name
// that is not valid Unicode still names the same file.
inline std::filesystem::path nativePath(const QString &path)
{
#ifdef Q_OS_WIN
    return std::filesystem::path(path.toStdWString());
#else
    return std::filesystem::path(QFile::encodeName(path).toStdString());
#endif
}

// The other way: a path the system gave (a link's target) as Qt shows it.
inline QString fromNativePath(const std::filesystem::path &path)
{
#ifdef Q_OS_WIN
    return QString::fromStdWString(path.wstring());
#else
    return QFile::decodeName(QByteArray::fromStdString(path.string()));
#endif
}

} // namespace lb::platform
