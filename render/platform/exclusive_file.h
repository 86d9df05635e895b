#pragma once
// A file this process makes new (never someone else's: the creation fails when the name is
// taken, even by a link), writes whole, flushes to the disk and then puts in another file's
// place in one step, or removes: what the writer (render/model/io/safe_write.h) makes its
// temporary files with. Linux: open(O_EXCL), write, fchmod, fsync, close, rename, unlink, as
// the writer did itself. The portable layer: QFile with QIODevice::NewOnly and
// std::filesystem::rename; it cannot flush to the disk (portable/exclusive_file.cpp).

#include "file_status.h"

#include <QString>

#include <cstddef>
#include <memory>

namespace lb::platform {

class ExclusiveFile
{
public:
    ExclusiveFile();
    ~ExclusiveFile(); // discard()
    ExclusiveFile(const ExclusiveFile &) = delete;
    ExclusiveFile &operator=(const ExclusiveFile &) = delete;

    // Creates `path`, which must not exist (FileError::Exists: take another name), with the
    // permissions of any new file (0666 less the umask).
    FileError create(const QString &path);
    // The permissions (the 07777 bits) the file is to have instead: the old target's.
    void keepPermissions(unsigned permissions);
    // All `size` bytes, or the system's reason why not.
    FileError writeAll(const char *data, std::size_t size);
    // Flushes to the disk and closes: some file systems report a full disk or a quota only
    // here (NFS), or at the close.
    FileError finish();
    // Renames the finished file over `target`, which it replaces in one step; from then on
    // the file is no longer this one's to remove.
    FileError commitOver(const QString &target);
    // Closes and removes the file, unless it was committed.
    void discard();

private:
    struct Handle; // the system's side: a descriptor, or a QFile
    std::unique_ptr<Handle> m_handle;
};

// A write beyond the file size limit (`ulimit -f`, a quota) raises SIGXFSZ where the system
// has it, which kills the process without a word; ignored, the write fails with EFBIG ("File
// too large") and is reported like any other failure.
void reportFileSizeLimitAsError();

} // namespace lb::platform
