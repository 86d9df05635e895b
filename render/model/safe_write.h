#pragma once
// Every file the workbench writes (scenes, shaders, images) goes through here: a target that
// exists and is not a regular file (a device such as /dev/null, a FIFO, a folder) is refused,
// since a save would replace it, and the bytes go to a temporary file beside the target that
// is renamed over it only once complete, so a kill during the write leaves the old file whole.

#include <QByteArray>
#include <QImage>
#include <QString>

#include <utility>
#include <vector>

namespace lb {

// Why `path` may not be written ("PATH: not a regular file ..."); empty when it may.
QString unwritableTarget(const QString &path);
// Returns empty, or "PATH: why".
QString writeFileSafely(const QString &path, const QByteArray &bytes);
// Files that belong together (a shader pair): every one is written to its temporary file
// before any is renamed, so a failed write changes none of them.
QString writeFilesSafely(const std::vector<std::pair<QString, QByteArray>> &files);
// An image in the format its suffix names (PNG without one), `quality` as QImageWriter's.
QString writeImageSafely(const QString &path, const QImage &image, int quality = -1);

} // namespace lb
