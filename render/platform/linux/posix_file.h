#pragma once
// What the Linux files of this room share: errno and struct stat in the platform's words.

#include "file_status.h"

#include <cerrno>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

namespace lb::platform::posix {

inline FileError errorFrom(int error)
{
    FileError e;
    e.code = error == ENOENT   ? FileError::Missing
             : error == ELOOP  ? FileError::Loop
             : error == EEXIST ? FileError::Exists
                               : FileError::Other;
    e.reason = std::strerror(error);
    return e;
}

inline FileKind kindOf(mode_t mode)
{
    if (S_ISREG(mode))
        return FileKind::Regular;
    if (S_ISDIR(mode))
        return FileKind::Folder;
    if (S_ISLNK(mode))
        return FileKind::Link;
    if (S_ISFIFO(mode))
        return FileKind::Fifo;
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return FileKind::Device;
    if (S_ISSOCK(mode))
        return FileKind::Socket;
    return FileKind::Other;
}

inline FileStatus statusOf(const struct stat &st)
{
    FileStatus s;
    s.kind = kindOf(st.st_mode);
    s.size = std::uint64_t(st.st_size);
    s.permissions = unsigned(st.st_mode & 07777);
    s.ownedByThisUser = st.st_uid == ::geteuid();
    return s;
}

} // namespace lb::platform::posix
