#include "file_status.h"

#include "posix_file.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <string>

#include <fcntl.h>

#include <unistd.h>

namespace lb::platform {

using posix::errorFrom;

bool canTellOwners()
{
    return true;
}

FileStatus fileStatus(const std::filesystem::path &path, Links links)
{
    struct stat st;
    if ((links == Links::Keep ? ::lstat(path.c_str(), &st) : ::stat(path.c_str(), &st)) != 0) {
        FileStatus s;
        s.error = errorFrom(errno);
        return s;
    }
    return posix::statusOf(st);
}

std::filesystem::path linkTarget(const std::filesystem::path &link, FileError &error)
{
    std::string target(PATH_MAX, '\0');
    const ssize_t n = ::readlink(link.c_str(), target.data(), target.size());
    if (n < 0) {
        error = errorFrom(errno);
        return {};
    }
    target.resize(std::size_t(n));
    error = {};
    return target;
}

std::filesystem::path resolvedPath(const std::filesystem::path &path, FileError &error)
{
    char *r = ::realpath(path.c_str(), nullptr);
    if (!r) {
        error = errorFrom(errno);
        return {};
    }
    std::filesystem::path result(r);
    std::free(r);
    error = {};
    return result;
}

FileError creatingFilesRefused(const std::filesystem::path &folder)
{
    // Writing a name in a folder takes write and search permission on it.
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return errorFrom(errno);
    return {};
}

FileError fileCreationFails(const std::filesystem::path &folder)
{
    // Permission is not all: root may "write" /proc and /sys, which take no files (--sheets
    // /proc passed the permission check and then failed every sheet). An empty file made and
    // removed at once says what the folder does.
    for (int attempt = 0; attempt < 8; ++attempt) {
        const std::filesystem::path probe =
            folder / (".lightbench-probe-" + std::to_string(::getpid()) + "-" +
                      std::to_string(std::rand() % 1000000));
        const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0) {
            ::close(fd);
            ::unlink(probe.c_str());
            return {};
        }
        if (errno != EEXIST)
            return errorFrom(errno);
    }
    return {};
}

} // namespace lb::platform
