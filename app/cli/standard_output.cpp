#include "standard_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace lb {

namespace {
bool g_closed = false;
}

void setStandardOutputWasClosed(bool closed)
{
    g_closed = closed;
}

QString writeStandardOutput(const QByteArray &bytes)
{
    if (g_closed)
        return QStringLiteral("standard output is closed");
    errno = 0;
    const bool written = std::fwrite(bytes.constData(), 1, std::size_t(bytes.size()), stdout) ==
                             std::size_t(bytes.size()) &&
                         std::fflush(stdout) == 0 && !std::ferror(stdout);
    if (written)
        return {};
    const int error = errno;
    std::clearerr(stdout);
    return error ? QStringLiteral("could not write to standard output (%1)")
                       .arg(QString::fromLocal8Bit(std::strerror(error)))
                 : QStringLiteral("could not write to standard output");
}

} // namespace lb
