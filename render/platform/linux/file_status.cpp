#include "file_status.h"

#include "posix_file.h"

#include <climits>
#include <cstdlib>

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

} // namespace lb::platform
