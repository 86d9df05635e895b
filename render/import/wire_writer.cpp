#include "wire_writer.h"

#include "stream_output.h"

namespace lb::wire {

Writer::Writer(platform::StreamOutput &out) : m_out(out)
{
    m_buffer.reserve(kBufferBytes);
    write(kMagic, sizeof kMagic);
}

Writer::~Writer()
{
    flush();
}

void Writer::record(Record type, const void *payload, std::size_t size)
{
    begin(type, size);
    write(payload, size);
}

void Writer::begin(Record type, std::uint64_t size)
{
    RecordHeader header;
    header.type = std::uint32_t(type);
    header.size = size;
    write(&header, sizeof header);
}

void Writer::write(const void *data, std::size_t size)
{
    if (size >= kBufferBytes) { // large arrays go out directly
        flush();
        writeAll(static_cast<const char *>(data), size);
        return;
    }
    if (m_buffer.size() + size > kBufferBytes)
        flush();
    const char *p = static_cast<const char *>(data);
    m_buffer.insert(m_buffer.end(), p, p + size);
}

void Writer::flush()
{
    writeAll(m_buffer.data(), m_buffer.size());
    m_buffer.clear();
}

int Writer::fail(const std::string &message, int exitCode)
{
    text(Record::Error, message);
    flush();
    return exitCode;
}

void Writer::writeAll(const char *p, std::size_t size)
{
    if (m_ok && size > 0 && !m_out.writeAll(p, size))
        m_ok = false; // the reader went away
}

} // namespace lb::wire
