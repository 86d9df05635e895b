#include "terminal.h"

#ifdef _WIN32
#include <io.h>
#endif

// Standard C++ cannot ask whether a stream is a terminal; only Windows' C runtime is asked
// here. Elsewhere the answer is no: a progress line missing costs nothing, one written into a
// log file would fill it with carriage returns.

namespace lb::platform {

bool isTerminal(std::FILE *stream)
{
#ifdef _WIN32
    return stream && _isatty(_fileno(stream)) != 0;
#else
    (void)stream;
    return false;
#endif
}

} // namespace lb::platform
