#include "fast_mesh_readers.h"

#include <assimp/IOStream.hpp>

#include <algorithm>
#include <cstring>

namespace lb {

Chunks::Chunks(Assimp::IOStream &file, const ReadProgress &progress)
    : m_file(file), m_progress(progress), m_buffer(kBytes), m_size(file.FileSize())
{
}

bool Chunks::fill()
{
    if (m_stopped)
        return false;
    std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
    m_end -= m_begin;
    m_begin = 0;
    const std::size_t got = m_file.Read(m_buffer.data() + m_end, 1, m_buffer.size() - m_end);
    m_end += got;
    m_fileRead += got;
    if (m_progress && m_size > 0 && !m_progress(float(double(m_fileRead) / double(m_size))))
        m_stopped = true;
    return got > 0 && !m_stopped;
}

const unsigned char *Chunks::take(std::size_t n)
{
    while (m_end - m_begin < n)
        if (!fill())
            return nullptr;
    const unsigned char *p = m_buffer.data() + m_begin;
    m_begin += n;
    m_offset += n;
    return p;
}

bool Chunks::read(void *to, std::size_t n)
{
    auto *out = static_cast<unsigned char *>(to);
    while (n > 0) {
        if (m_begin == m_end && !fill())
            return false;
        const std::size_t step = std::min(n, m_end - m_begin);
        std::memcpy(out, m_buffer.data() + m_begin, step);
        m_begin += step;
        m_offset += step;
        out += step;
        n -= step;
    }
    return true;
}

bool Chunks::line(std::string &to, std::size_t maxBytes)
{
    to.clear();
    for (;;) {
        if (m_begin == m_end && !fill())
            return !to.empty();
        const unsigned char *start = m_buffer.data() + m_begin;
        const auto *nl =
            static_cast<const unsigned char *>(std::memchr(start, '\n', m_end - m_begin));
        const std::size_t step = nl ? std::size_t(nl - start) : m_end - m_begin;
        if (to.size() + step > maxBytes)
            return false;
        to.append(reinterpret_cast<const char *>(start), step);
        m_begin += step + (nl ? 1 : 0);
        m_offset += step + (nl ? 1 : 0);
        if (nl) {
            if (!to.empty() && to.back() == '\r')
                to.pop_back();
            return true;
        }
    }
}

} // namespace lb
