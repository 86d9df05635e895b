#include "stream_output.h"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace lb::platform {

struct StreamOutput::Channel
{
    int fd = -1;
};

void useBinaryStandardStreams() {} // POSIX streams are binary

StreamOutput::StreamOutput() : m_channel(new Channel)
{
    // The stream gets stdout's descriptor to itself; anything an importer prints on stdout
    // goes to stderr instead of corrupting the stream.
    m_channel->fd = ::dup(STDOUT_FILENO);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    // A 1 MiB pipe (the unprivileged maximum) instead of 64 KiB: 16 times fewer round trips
    // between the two processes for a big mesh. Fails harmlessly when stdout is no pipe.
    ::fcntl(m_channel->fd, F_SETPIPE_SZ, 1 << 20);
}

StreamOutput::~StreamOutput() = default;

bool StreamOutput::writeAll(const char *data, std::size_t size)
{
    while (size > 0) {
        const ssize_t n = ::write(m_channel->fd, data, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

} // namespace lb::platform
