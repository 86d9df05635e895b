#include "read_only_file.h"

#include "posix_file.h"

#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace lb::platform {

struct ReadOnlyFile::Handle
{
    std::FILE *file = nullptr; // read through stdio's buffer, as Assimp's own stream does
};

namespace {

FileStatus failure(int error)
{
    FileStatus s;
    s.error = posix::errorFrom(error);
    return s;
}

} // namespace

std::unique_ptr<ReadOnlyFile> ReadOnlyFile::open(const std::filesystem::path &path,
                                                 FileStatus &opened)
{
    // O_NONBLOCK: a FIFO put there meanwhile does not hang the open itself.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY | O_NOFOLLOW);
    if (fd < 0) {
        opened = failure(errno);
        return nullptr;
    }
    struct stat st;
    if (::fstat(fd, &st) != 0) {
        opened = failure(errno);
        ::close(fd);
        return nullptr;
    }
    opened = posix::statusOf(st);
    if (opened.kind != FileKind::Regular) {
        ::close(fd);
        return nullptr;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    auto handle = std::make_unique<Handle>();
    handle->file = ::fdopen(fd, "rb");
    if (!handle->file) {
        opened = failure(errno);
        ::close(fd);
        return nullptr;
    }
    return std::unique_ptr<ReadOnlyFile>(new ReadOnlyFile(std::move(handle)));
}

ReadOnlyFile::ReadOnlyFile(std::unique_ptr<Handle> handle) : m_handle(std::move(handle)) {}

ReadOnlyFile::~ReadOnlyFile()
{
    std::fclose(m_handle->file);
}

std::size_t ReadOnlyFile::read(void *buffer, std::size_t size, std::size_t count)
{
    return std::fread(buffer, size, count, m_handle->file);
}

bool ReadOnlyFile::seek(std::uint64_t offset)
{
    return ::fseeko(m_handle->file, off_t(offset), SEEK_SET) == 0;
}

long long ReadOnlyFile::position()
{
    return ::ftello(m_handle->file);
}

} // namespace lb::platform
