#include "signal_names.h"

#include <cstring>

namespace lb::platform {

QString signalName(int signal)
{
    return QString::fromLocal8Bit(::strsignal(signal));
}

} // namespace lb::platform
