#pragma once
// The import helper's binary stream (render/import/wire.h) on its standard output. Linux gives
// the stream stdout's descriptor to itself (what an importer prints on stdout goes to stderr
// instead of into the stream) and a 1 MiB pipe; the portable layer writes to stdout through
// stdio and can do neither (portable/stream_output.cpp).

#include <cstddef>
#include <memory>

namespace lb::platform {

// The standard streams (0, 1, 2) that were closed when the process started, as bits (1 << fd),
// each now open on the null device, so that no file, pipe or socket opened later takes its
// number: with descriptor 1 closed, the X server's socket became stdout and a report written
// there went into the X connection (the batch hung). Call first in main. The portable layer
// can neither tell nor reopen a closed descriptor and returns 0.
unsigned reopenClosedStandardStreams();
// Whether reopenClosedStandardStreams() can (false in the portable layer): the tests of a closed
// stdout skip where it cannot.
bool canReopenStandardStreams();

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
