#include "file_status.h"

#include <QFileInfo>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

// std::filesystem answers what lstat, stat, readlink and realpath answer, with the system's
// words in its error_code. Standard C++ has no access(): whether a folder takes new files is
// QFileInfo::isWritable() (write permission only; a folder without search permission is let
// through, and the temporary file's creation then fails with the system's reason).

namespace lb::platform {

namespace {

namespace fs = std::filesystem;

FileError errorFrom(const std::error_code &ec)
{
    FileError e;
    e.code = ec == std::errc::no_such_file_or_directory       ? FileError::Missing
             : ec == std::errc::too_many_symbolic_link_levels ? FileError::Loop
             : ec == std::errc::file_exists                   ? FileError::Exists
                                                              : FileError::Other;
    e.reason = ec.message();
    return e;
}

FileKind kindOf(fs::file_type type)
{
    switch (type) {
    case fs::file_type::regular:
        return FileKind::Regular;
    case fs::file_type::directory:
        return FileKind::Folder;
    case fs::file_type::symlink:
        return FileKind::Link;
    case fs::file_type::fifo:
        return FileKind::Fifo;
    case fs::file_type::block:
    case fs::file_type::character:
        return FileKind::Device;
    case fs::file_type::socket:
        return FileKind::Socket;
    default:
        return FileKind::Other;
    }
}

} // namespace

// The standard has no owners, and QFileInfo's are numbers this layer cannot compare with
// the process's user.
bool canTellOwners()
{
    return false;
}

FileStatus fileStatus(const fs::path &path, Links links)
{
    FileStatus s;
    std::error_code ec;
    const fs::file_status st =
        links == Links::Keep ? fs::symlink_status(path, ec) : fs::status(path, ec);
    if (st.type() == fs::file_type::not_found && !ec) // not an error to the standard
        ec = std::make_error_code(std::errc::no_such_file_or_directory);
    if (ec || st.type() == fs::file_type::none) {
        s.error = errorFrom(ec ? ec : std::make_error_code(std::errc::io_error));
        return s;
    }
    s.kind = kindOf(st.type());
    if (s.kind == FileKind::Regular) {
        const std::uintmax_t size = fs::file_size(path, ec);
        s.size = ec ? 0 : std::uint64_t(size);
    }
    if (st.permissions() != fs::perms::unknown) // the standard numbers them as POSIX does
        s.permissions = unsigned(st.permissions()) & 07777u;
    return s;
}

fs::path linkTarget(const fs::path &link, FileError &error)
{
    std::error_code ec;
    fs::path target = fs::read_symlink(link, ec);
    error = ec ? errorFrom(ec) : FileError{};
    return ec ? fs::path() : target;
}

fs::path resolvedPath(const fs::path &path, FileError &error)
{
    std::error_code ec;
    fs::path result = fs::canonical(path, ec);
    error = ec ? errorFrom(ec) : FileError{};
    return ec ? fs::path() : result;
}

FileError creatingFilesRefused(const fs::path &folder)
{
    if (const FileStatus st = fileStatus(folder, Links::Follow); st.error)
        return st.error; // as access() says it: missing, a loop, "Not a directory"
    if (QFileInfo(folder).isWritable())
        return {};
    return errorFrom(std::make_error_code(std::errc::permission_denied));
}

FileError fileCreationFails(const fs::path &folder)
{
    // C's "x" mode (C11; glibc, macOS and Microsoft's runtime have it): made new or not at all.
    for (int attempt = 0; attempt < 8; ++attempt) {
        const fs::path probe =
            folder / (".lightbench-probe-" + std::to_string(std::rand() % 100000000));
        errno = 0;
        if (std::FILE *f = std::fopen(probe.string().c_str(), "wx")) {
            std::fclose(f);
            std::error_code ec;
            fs::remove(probe, ec);
            return {};
        }
        if (errno != EEXIST)
            return errorFrom(std::error_code(errno ? errno : EACCES, std::generic_category()));
    }
    return {};
}

} // namespace lb::platform
