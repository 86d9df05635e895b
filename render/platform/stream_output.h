#pragma once
// The import helper's binary stream (render/import/wire.h) on its standard output. Linux gives
// the stream stdout's descriptor to itself (what an importer prints on stdout goes to stderr
// instead of into the stream) and a 1 MiB pipe; the portable layer writes to stdout through
// stdio and can do neither (portable/stream_output.cpp).

#include <cstddef>
#include <memory>

namespace lb::platform {

// Standard input and output carry bytes as they are, for the helpers' binary messages:
// nothing to do on Linux (and macOS); Windows' C runtime would turn "\n" into "\r\n".
void useBinaryStandardStreams();

class StreamOutput
{
public:
    // Takes standard output for the stream from here on (the helper's usage and --formats
    // print before).
    StreamOutput();
    ~StreamOutput();
    StreamOutput(const StreamOutput &) = delete;
    StreamOutput &operator=(const StreamOutput &) = delete;

    // All `size` bytes; false when they could not be written (the reader went away).
    bool writeAll(const char *data, std::size_t size);

private:
    struct Channel; // the system's side: a descriptor, or stdio's stdout
    std::unique_ptr<Channel> m_channel;
};

} // namespace lb::platform
