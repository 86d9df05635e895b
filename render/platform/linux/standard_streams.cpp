#include "standard_streams.h"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace lb::platform {

bool canReopenStandardStreams()
{
    return true;
}

unsigned reopenClosedStandardStreams()
{
    unsigned closed = 0;
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF)
            continue;
        // open() takes the lowest free number: this one, the lower ones being open by now.
        const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
        if (opened >= 0 && opened != fd) { // cannot happen; never leave a stray descriptor
            ::dup2(opened, fd);
            ::close(opened);
        }
        closed |= 1u << fd;
    }
    return closed;
}

} // namespace lb::platform
