#pragma once
// Writes the import stream (wire.h) to the helper's standard output (platform/stream_output.h)
// through a buffer. Used by the helper only; plain C++.

#include "wire.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lb::platform {
class StreamOutput;
}

namespace lb::wire {

// The writer's buffer: a write() of at least this many bytes goes out directly, not copied.
constexpr std::size_t kBufferBytes = 1 << 20;

class Writer
{
public:
    explicit Writer(platform::StreamOutput &out);
    ~Writer();
    Writer(const Writer &) = delete;
    Writer &operator=(const Writer &) = delete;

    // A whole record at once.
    void record(Record type, const void *payload, std::size_t size);
    void text(Record type, const std::string &text) { record(type, text.data(), text.size()); }
    // A record whose payload follows in write() calls that add up to `size` bytes.
    void begin(Record type, std::uint64_t size);
    void write(const void *data, std::size_t size);
    void flush();
    // The helper's last word: an Error record saying `message`, sent at once; gives back
    // `exitCode`, the exit code that goes with it.
    int fail(const std::string &message, int exitCode = kExitFailed);
    // False once a write failed (the reader went away); later writes are dropped.
    bool ok() const { return m_ok; }

private:
    void writeAll(const char *p, std::size_t size);

    platform::StreamOutput &m_out;
    bool m_ok = true;
    std::vector<char> m_buffer;
};

} // namespace lb::wire
