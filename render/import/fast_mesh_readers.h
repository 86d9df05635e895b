#pragma once
// The import helper's own readers for the files scans come in: binary and ASCII PLY (a vertex
// element of scalars, then a face list) and binary STL. Assimp's PLY reader builds a document of
// every value before it makes a mesh (a 10M-triangle scan: 3 s and 390 MB); these read straight
// into the arrays the stream sends. They give what Assimp gives for the same file (the same
// vertices, normals, colours and default material; tests/import/test_fast_readers.cpp compares
// the two), and decline any file they do not fully understand, which Assimp then reads.
// Plain C++ over Assimp's IOStream (the confined file the helper opened): the helper only.

#include "wire.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace Assimp {
class IOStream;
}

namespace lb {

struct FastMesh
{
    std::vector<float> positions;         // x, y, z a vertex
    std::vector<float> normals;           // x, y, z a vertex, or empty
    std::vector<float> colors;            // r, g, b a vertex, or empty
    std::vector<std::uint32_t> triangles; // three corners a face, as the file gives them
    std::uint64_t skippedFaces = 0;       // faces of fewer than three corners
    wire::MaterialRecord material;        // the material Assimp makes for the same file
};

enum class FastRead {
    Read,     // `mesh` holds the file
    Declined, // not a file these readers understand whole: let Assimp read it
    Failed,   // the file is broken in a way these readers can say (`why`): it is refused
};

// Called as the file is read with the fraction of its bytes read; false stops the reading
// (the workbench went away), which fails it.
using ReadProgress = std::function<bool(float fraction)>;

// `why`: a Declined file's reason (for a test or a log) or a Failed one's message.
FastRead readPly(Assimp::IOStream &file, FastMesh &mesh, std::string &why,
                 const ReadProgress &progress);
FastRead readBinaryStl(Assimp::IOStream &file, FastMesh &mesh, std::string &why,
                       const ReadProgress &progress);

// Reads an IOStream a megabyte at a time: the fast readers' only way to the bytes.
class Chunks
{
public:
    Chunks(Assimp::IOStream &file, const ReadProgress &progress);

    std::uint64_t size() const { return m_size; }
    std::uint64_t left() const { return m_size - m_offset; } // bytes not yet taken
    bool stopped() const { return m_stopped; }

    // The next `n` bytes, into `to`; false when the file ends first (or the reading stopped).
    bool read(void *to, std::size_t n);
    // A line without its '\n' (and '\r'); false at the end of the file or past `maxBytes`.
    bool line(std::string &to, std::size_t maxBytes);
    // The next `n` bytes in the buffer (n <= kBytes), refilled as needed; null at the end.
    const unsigned char *take(std::size_t n);

    static constexpr std::size_t kBytes = 1 << 20;

private:
    bool fill(); // moves what is left to the front and reads more; false when nothing came

    Assimp::IOStream &m_file;
    const ReadProgress &m_progress;
    std::vector<unsigned char> m_buffer;
    std::size_t m_begin = 0, m_end = 0; // the bytes of m_buffer not yet taken
    std::uint64_t m_size = 0, m_offset = 0, m_fileRead = 0;
    bool m_stopped = false;
};

} // namespace lb
