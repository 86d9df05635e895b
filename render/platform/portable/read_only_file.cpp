#include "read_only_file.h"

#include <cerrno>
#include <fstream>
#include <system_error>

// Standard C++ opens by name only: no "do not follow a link", no "do not wait", no status of
// the file once open. So the name is looked at (links kept) just before the open and only a
// regular file is opened; a FIFO put in its place between that look and the open would hold
// the open until the workbench's time limit ends the helper. A std::ifstream, not stdio:
// its offsets are 64-bit everywhere (a long is 32 on Windows).

namespace lb::platform {

struct ReadOnlyFile::Handle
{
    std::ifstream file;
};

std::unique_ptr<ReadOnlyFile> ReadOnlyFile::open(const std::filesystem::path &path,
                                                 FileStatus &opened)
{
    opened = fileStatus(path, Links::Keep); // a link put there meanwhile is refused as one
    if (opened.error || opened.kind != FileKind::Regular)
        return nullptr;
    auto handle = std::make_unique<Handle>();
    errno = 0;
    handle->file.open(path, std::ios::in | std::ios::binary);
    if (!handle->file.is_open()) {
        // The standard does not say that a failed open sets errno; the C libraries under
        // every std::filebuf do ("Permission denied").
        const int error = errno;
        opened = {};
        opened.error.code = error == ENOENT ? FileError::Missing : FileError::Other;
        opened.error.reason =
            error != 0 ? std::generic_category().message(error) : std::string("cannot be opened");
        return nullptr;
    }
    return std::unique_ptr<ReadOnlyFile>(new ReadOnlyFile(std::move(handle)));
}

ReadOnlyFile::ReadOnlyFile(std::unique_ptr<Handle> handle) : m_handle(std::move(handle)) {}

ReadOnlyFile::~ReadOnlyFile() = default;

std::size_t ReadOnlyFile::read(void *buffer, std::size_t size, std::size_t count)
{
    if (size == 0)
        return 0;
    m_handle->file.read(static_cast<char *>(buffer), std::streamsize(size * count));
    const std::size_t bytes = std::size_t(m_handle->file.gcount());
    m_handle->file.clear(); // a short read sets eof and fail: the next seek must still work
    return bytes / size;
}

bool ReadOnlyFile::seek(std::uint64_t offset)
{
    m_handle->file.clear();
    return bool(m_handle->file.seekg(std::streamoff(offset), std::ios::beg));
}

long long ReadOnlyFile::position()
{
    return (long long)m_handle->file.tellg();
}

} // namespace lb::platform
