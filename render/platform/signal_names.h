#pragma once
// The system's name for a signal, as a message about a child that died of it shows it
// ("Segmentation fault"): strsignal on Linux; the portable layer names the six signals of
// standard C in the same words (glibc's) and says "Unknown signal N" for the rest.

#include <QString>

namespace lb::platform {

QString signalName(int signal);

} // namespace lb::platform
