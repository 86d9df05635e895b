#pragma once
// A regular file opened for reading by the import helper, after its checks (confined_io_system):
// only a regular file is opened, and its status is that of the file opened, for the checks to
// be made again on it. Linux opens with O_NOFOLLOW | O_NONBLOCK and asks fstat, so that a link
// or a FIFO put in the file's place after the check neither leads elsewhere nor hangs the open.
// The portable layer can only look at the name again just before opening it (a window remains:
// portable/read_only_file.cpp).

#include "file_status.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

namespace lb::platform {

class ReadOnlyFile
{
public:
    // `path`: links already resolved. Null when nothing was opened: `opened.error` says why,
    // or `opened.kind` is no regular file's; else `opened` is the status of what was opened.
    static std::unique_ptr<ReadOnlyFile> open(const std::filesystem::path &path,
                                              FileStatus &opened);
    ~ReadOnlyFile();
    ReadOnlyFile(const ReadOnlyFile &) = delete;
    ReadOnlyFile &operator=(const ReadOnlyFile &) = delete;

    // Up to `count` items of `size` bytes, as std::fread: the number of whole items read.
    std::size_t read(void *buffer, std::size_t size, std::size_t count);
    // To `offset` bytes from the start; false where it cannot.
    bool seek(std::uint64_t offset);
    // Where the next read starts, -1 if unknown.
    long long position();

private:
    struct Handle; // the system's side: stdio's FILE, or a std::ifstream
    explicit ReadOnlyFile(std::unique_ptr<Handle> handle);
    std::unique_ptr<Handle> m_handle;
};

} // namespace lb::platform
