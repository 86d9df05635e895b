#pragma once
// The address space the process holds now (VmSize, in bytes; 0 when /proc cannot say), for
// the tests that set RLIMIT_AS a little above it so that one big allocation fails.
#include <QByteArray>
#include <QFile>

#include <sys/resource.h>

namespace lb::test {

inline rlim_t addressSpaceInUse()
{
    QFile status("/proc/self/status");
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray text = status.readAll();
    const qsizetype at = text.indexOf("VmSize:");
    if (at < 0)
        return 0;
    return text.mid(at + 7).trimmed().split(' ').first().toULongLong() * 1024; // kB
}

} // namespace lb::test
