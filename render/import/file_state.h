#pragma once
// What a file looked like when it failed to load (its existence, size and modification time),
// so that it is tried again once it changes (put back, saved again) and not before.

#include <QDateTime>
#include <QFileInfo>
#include <QString>

namespace lb {

inline QString fileState(const QString &path)
{
    const QFileInfo info(path);
    return info.exists()
               ? QString("%1 %2").arg(info.size()).arg(info.lastModified().toMSecsSinceEpoch())
               : QString();
}

} // namespace lb
