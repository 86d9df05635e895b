#pragma once
// What a path is (a regular file, a folder, a link, a FIFO, a device), with or without
// following its links, and the system's own words when it cannot be told: the checks the
// writer (safe_write) and the readers (bounded_read, the import helper's confined files) make
// before they touch a file. Linux asks lstat, stat, readlink, realpath and access; the
// portable layer asks std::filesystem (and QFileInfo where the standard has nothing), which
// gives the same answers except where noted in portable/file_status.cpp. No Qt here: the
// import helper uses it and links no Qt (qt_paths.h has the conversions for Qt's side).

#include <cstdint>
#include <filesystem>
#include <string>

namespace lb::platform {

// Why a call on a path failed. The callers word their messages from the code and show
// `reason` for the rest, so that a user reads what the system said ("Not a directory").
struct FileError
{
    enum Code {
        None,
        Missing, // no such file (ENOENT)
        Loop,    // a loop of symbolic links (ELOOP)
        Exists,  // a new file's name is taken (EEXIST)
        Other,   // anything else: `reason` says it
    };
    Code code = None;
    std::string reason; // the system's words, in the local 8-bit encoding; empty for None

    explicit operator bool() const { return code != None; }
};

enum class FileKind { Unknown, Regular, Folder, Link, Fifo, Device, Socket, Other };

struct FileStatus
{
    FileKind kind = FileKind::Unknown; // Unknown when `error` is set
    FileError error;
    std::uint64_t size = 0;   // a regular file's bytes
    unsigned permissions = 0; // the 07777 bits, numbered as POSIX does (0644: rw-r--r--)
    // Owned by this process's (effective) user; false where it cannot be told (the portable
    // layer: the standard has no owners), so that a check that needs it refuses.
    bool ownedByThisUser = false;
};

enum class Links { Follow, Keep };

// The status of `path` itself (Links::Keep: a link is a Link) or of what its links lead to.
FileStatus fileStatus(const std::filesystem::path &path, Links links);

// What the symbolic link `link` says, as it says it (relative to the link's folder unless it
// is absolute); empty with `error` set when it cannot be read.
std::filesystem::path linkTarget(const std::filesystem::path &link, FileError &error);

// `path` with every link, "." and ".." resolved, for a file that exists; empty with `error`
// set when there is none (Missing, Loop, or the system's reason).
std::filesystem::path resolvedPath(const std::filesystem::path &path, FileError &error);

// Whether FileStatus::ownedByThisUser is told here (false in the portable layer).
bool canTellOwners();

// Why this process may not create files in the folder `folder` (None when it may).
FileError creatingFilesRefused(const std::filesystem::path &folder);
// Why a file cannot be made in `folder` when one is tried (an empty one, removed at once): for
// the checks before a long run only (a batch's sheet folder), where permission alone misleads
// (/proc). The portable layer tries nothing and returns None.
FileError fileCreationFails(const std::filesystem::path &folder);

} // namespace lb::platform
