#include "terminal.h"

#include <unistd.h>

namespace lb::platform {

bool isTerminal(std::FILE *stream)
{
    return stream && ::isatty(::fileno(stream)) == 1;
}

} // namespace lb::platform
