#include "stream_output.h"

#include <cstdio>

#ifdef _WIN32 // the one system whose C runtime translates line ends on stdin and stdout
#include <fcntl.h>
#include <io.h>
#endif

// Standard C++ cannot move a descriptor: the stream shares stdout with anything an importer
// prints there. Assimp speaks through its logger, which the helper does not attach; a reader
// that printed on stdout all the same would break the stream, and the workbench would refuse
// it as broken (a message, not a wrong mesh). Nor can standard C++ size a pipe.

namespace lb::platform {

struct StreamOutput::Channel
{
};

void useBinaryStandardStreams()
{
#ifdef _WIN32
    _setmode(_fileno(stdin), _O_BINARY);
    _setmode(_fileno(stdout), _O_BINARY);
#endif
}

StreamOutput::StreamOutput() : m_channel(new Channel)
{
    useBinaryStandardStreams();
}

StreamOutput::~StreamOutput()
{
    std::fflush(stdout);
}

bool StreamOutput::writeAll(const char *data, std::size_t size)
{
    // The stream's writer buffers whole records: each of its writes goes out at once.
    return std::fwrite(data, 1, size, stdout) == size && std::fflush(stdout) == 0;
}

} // namespace lb::platform
