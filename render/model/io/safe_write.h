#pragma once
// Every file the workbench writes (scenes, shaders, images, reports, sheets) goes through here.
// - The target is resolved through its symbolic links; one that exists and is not a regular
//   file (a device such as /dev/null, a FIFO, a folder) is refused, since a save would replace
//   it; so is a folder that does not exist or cannot be written. unwritableTarget() says so
//   before any work is done, the writers again when they write.
// - The bytes go to a temporary file beside the target, written with every write, the final
//   flush to the disk (fsync) and the close checked; only then is it renamed over the target.
//   On any failure the old file is left exactly as it was, the temporary is removed, and the
//   message names the path and the system's reason ("No space left on device", "Disk quota
//   exceeded", "File too large", "Permission denied").
// Not QSaveFile: Qt 6.4's commit() renames the temporary over the target even when the flush
// at its close failed (ENOSPC on a full disk), which left a 0-byte scene and reported success.
// The system's calls are the platform room's (render/platform: file_status.h for the checks,
// exclusive_file.h for the temporary); its portable layer cannot flush to the disk.

#include <QByteArray>
#include <QImage>
#include <QString>

#include <utility>
#include <vector>

namespace lb {

// Why `path` may not be written ("PATH: why"); empty when it may. It also makes and removes an
// empty file in the folder: permission alone passes /proc for root.
QString unwritableTarget(const QString &path);
// Returns empty, or "PATH: why".
QString writeFileSafely(const QString &path, const QByteArray &bytes);
// Files that belong together (a shader pair): every one is written to its temporary file
// before any is renamed, so a failed write changes none of them.
QString writeFilesSafely(const std::vector<std::pair<QString, QByteArray>> &files);
// An image in the format its suffix names (PNG without one), `quality` as QImageWriter's.
QString writeImageSafely(const QString &path, const QImage &image, int quality = -1);

// The longest start of `name` whose bytes in the file system's encoding (UTF-8) are at most
// `maxBytes`, cut between characters: a file name may have 255 bytes, and 80 CJK characters
// are 80 UTF-16 units but 240 bytes.
QString leftInBytes(const QString &name, int maxBytes);

// A write beyond the file size limit (`ulimit -f`, a quota) raises SIGXFSZ, which kills the
// process without a word; ignored, the write fails with EFBIG ("File too large") and is
// reported like any other failure. The writers call it; main() calls it first of all so that
// output to standard out is covered too.
void reportFileSizeLimitAsError();

} // namespace lb
