#include "signal_names.h"

#include <csignal>

// Standard C++ names no signal: only these six are its own. A process killed by another one
// (SIGKILL, SIGBUS where the system has them) is said by number.

namespace lb::platform {

QString signalName(int signal)
{
    switch (signal) {
    case SIGABRT:
        return QStringLiteral("Aborted");
    case SIGFPE:
        return QStringLiteral("Floating point exception");
    case SIGILL:
        return QStringLiteral("Illegal instruction");
    case SIGINT:
        return QStringLiteral("Interrupt");
    case SIGSEGV:
        return QStringLiteral("Segmentation fault");
    case SIGTERM:
        return QStringLiteral("Terminated");
    default:
        return QStringLiteral("Unknown signal %1").arg(signal);
    }
}

} // namespace lb::platform
