#include "exclusive_file.h"

#include <QFile>

#include "posix_file.h"

#include <csignal>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace lb::platform {

using posix::errorFrom;

struct ExclusiveFile::Handle
{
    QByteArray path; // the file's, while it is ours to remove
    int fd = -1;
};

ExclusiveFile::ExclusiveFile() : m_handle(new Handle) {}

ExclusiveFile::~ExclusiveFile()
{
    discard();
}

FileError ExclusiveFile::create(const QString &path)
{
    discard();
    const QByteArray native = QFile::encodeName(path);
    // 0666 less the umask, as any new file; O_EXCL: never someone else's file, nor a link.
    m_handle->fd = ::open(native.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (m_handle->fd < 0)
        return errorFrom(errno);
    m_handle->path = native;
    return {};
}

void ExclusiveFile::keepPermissions(unsigned permissions)
{
    if (m_handle->fd >= 0)
        ::fchmod(m_handle->fd, mode_t(permissions & 07777));
}

FileError ExclusiveFile::writeAll(const char *data, std::size_t size)
{
    for (std::size_t done = 0; done < size;) {
        const ssize_t n = ::write(m_handle->fd, data + done, size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return errorFrom(n < 0 ? errno : ENOSPC);
        done += std::size_t(n);
    }
    return {};
}

FileError ExclusiveFile::finish()
{
    // EINVAL, EROFS: a file that cannot be synchronised (a special file system), not a failure.
    if (::fsync(m_handle->fd) != 0 && errno != EINVAL && errno != EROFS)
        return errorFrom(errno);
    const int fd = std::exchange(m_handle->fd, -1);
    if (::close(fd) != 0 && errno != EINTR)
        return errorFrom(errno);
    return {};
}

FileError ExclusiveFile::commitOver(const QString &target)
{
    if (::rename(m_handle->path.constData(), QFile::encodeName(target).constData()) != 0)
        return errorFrom(errno);
    m_handle->path.clear();
    return {};
}

void ExclusiveFile::discard()
{
    if (m_handle->fd >= 0)
        ::close(std::exchange(m_handle->fd, -1));
    if (!m_handle->path.isEmpty())
        ::unlink(m_handle->path.constData());
    m_handle->path.clear();
}

void reportFileSizeLimitAsError()
{
    std::signal(SIGXFSZ, SIG_IGN);
}

} // namespace lb::platform
