#include "confined_io_system.h"

#include "file_status.h"
#include "read_only_file.h"

#include <assimp/IOStream.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <memory>
#include <utility>

namespace lb {

namespace {

// The path with links, "." and ".." resolved, or empty (`error` says why). Folders are
// separated by '/' on every system, as the names Assimp gives are.
std::string resolved(const std::string &path, platform::FileError &error)
{
    return platform::resolvedPath(path, error).generic_string();
}

std::string resolved(const std::string &path)
{
    platform::FileError error;
    return resolved(path, error);
}

std::string folderOf(const std::string &path)
{
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string withSlash(std::string folder)
{
    if (folder.empty() || folder.back() != '/')
        folder += '/';
    return folder;
}

// As a message says it, rounded up: "4096 MB", "640 KiB" (the window's sizeForMessage).
std::string sizeText(std::uint64_t bytes)
{
    const bool mega = bytes >= 10ull << 20;
    const std::uint64_t unit = mega ? 1ull << 20 : 1ull << 10;
    return std::to_string((bytes + unit - 1) / unit) + (mega ? " MB" : " KiB");
}

const char *kindOf(platform::FileKind kind)
{
    switch (kind) {
    case platform::FileKind::Fifo:
        return "a FIFO";
    case platform::FileKind::Folder:
        return "a folder";
    case platform::FileKind::Device:
        return "a device";
    case platform::FileKind::Socket:
        return "a socket";
    default:
        return "not a file";
    }
}

bool endsWithMtl(const std::string &path)
{
    if (path.size() < 4)
        return false;
    std::string tail = path.substr(path.size() - 4);
    std::transform(tail.begin(), tail.end(), tail.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ".mtl";
}

// A file opened for reading, never read past the size that was checked: a file that grows
// meanwhile reads as it was.
class BoundedStream : public Assimp::IOStream
{
public:
    BoundedStream(std::unique_ptr<platform::ReadOnlyFile> file, std::uint64_t size)
        : m_file(std::move(file)), m_size(size)
    {
    }

    size_t Read(void *buffer, size_t size, size_t count) override
    {
        if (size == 0 || count == 0 || m_pos >= m_size)
            return 0;
        const size_t items = std::min<std::uint64_t>(count, (m_size - m_pos) / size);
        const size_t n = m_file->read(buffer, size, items);
        if (n == items) {
            m_pos += std::uint64_t(n) * size;
        } else { // shrunk meanwhile, or a read error: where are we now
            const long long at = m_file->position();
            m_pos = at < 0 ? m_size : std::uint64_t(at);
        }
        return n;
    }
    size_t Write(const void *, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override
    {
        // Offsets from the end or the current place may be negative, passed as size_t.
        const long long delta = static_cast<long long>(offset);
        const long long base = origin == aiOrigin_SET   ? 0
                               : origin == aiOrigin_CUR ? (long long)m_pos
                                                        : (long long)m_size;
        const long long target = origin == aiOrigin_SET ? (long long)offset : base + delta;
        if (target < 0 || std::uint64_t(target) > m_size || !m_file->seek(std::uint64_t(target)))
            return aiReturn_FAILURE;
        m_pos = std::uint64_t(target);
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return size_t(m_pos); }
    size_t FileSize() const override { return size_t(m_size); }
    void Flush() override {}

private:
    std::unique_ptr<platform::ReadOnlyFile> m_file;
    std::uint64_t m_size;
    std::uint64_t m_pos = 0;
};

} // namespace

ConfinedIOSystem::ConfinedIOSystem(const std::string &meshPath, std::uint64_t maxBytes,
                                   std::string maxBytesWhy)
    : m_meshPath(meshPath), m_meshResolved(resolved(meshPath)),
      m_meshFolder(withSlash(folderOf(meshPath))), m_root(resolved(folderOf(meshPath))),
      m_maxBytes(maxBytes), m_maxBytesWhy(std::move(maxBytesWhy))
{
    if (!m_root.empty()) // else nothing is inside it: no side file is read
        m_root = withSlash(m_root);
}

std::string ConfinedIOSystem::shown(const std::string &path) const
{
    // Assimp joins names with a '/' of its own ("folder//name"), and retries a name it
    // could not open in other spellings: one spelling for all, so each file is said once.
    std::string name;
    for (const char c : path)
        if (c != '/' || name.empty() || name.back() != '/')
            name += c;
    if (name.compare(0, m_meshFolder.size(), m_meshFolder) == 0)
        name = name.substr(m_meshFolder.size());
    // The name comes from the file: one line, of a length a message can hold.
    for (char &c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = '?';
    if (name.size() > 300)
        name = name.substr(0, 140) + "..." + name.substr(name.size() - 140);
    return name;
}

void ConfinedIOSystem::note(const std::string &problem) const
{
    constexpr std::size_t kMaxProblems = 20; // a file naming thousands of others
    if (m_problems.size() < kMaxProblems &&
        std::find(m_problems.begin(), m_problems.end(), problem) == m_problems.end())
        m_problems.push_back(problem);
}

ConfinedIOSystem::Check ConfinedIOSystem::check(const std::string &path,
                                                const platform::FileStatus *opened) const
{
    using platform::FileError;
    Check c;
    FileError error;
    const std::string real = resolved(path, error);
    if (error) {
        c.missing = error.code == FileError::Missing;
        c.problem = shown(path) + ": " +
                    (c.missing                       ? std::string("no such file")
                     : error.code == FileError::Loop ? std::string("a loop of symbolic links")
                                                     : error.reason);
        return c;
    }
    // The mesh itself may be anywhere (the user chose it); what it names stays below it.
    const bool isMesh = real == m_meshResolved;
    const platform::FileStatus st =
        opened ? *opened : platform::fileStatus(real, platform::Links::Follow);
    if (st.error) {
        c.problem = shown(path) + ": " + st.error.reason;
        return c;
    }
    if (st.kind != platform::FileKind::Regular) {
        c.problem = shown(path) + ": not a regular file (" + kindOf(st.kind) + ")";
        return c;
    }
    if (!isMesh && (m_root.empty() || real.compare(0, m_root.size(), m_root) != 0)) {
        c.problem = shown(path) + ": outside the mesh's folder";
        return c;
    }
    c.size = st.size;
    const bool library = !isMesh && endsWithMtl(path);
    const std::uint64_t limit =
        library ? std::min(m_maxBytes, kMaxMaterialLibraryBytes) : m_maxBytes;
    if (c.size > limit) {
        const char *kind = isMesh    ? "a mesh file"
                           : library ? "a material library"
                                     : "a file a mesh refers to";
        c.problem = shown(path) + ": " + sizeText(c.size) + " is more than " + kind + " may be (" +
                    sizeText(limit) +
                    (limit == m_maxBytes && !m_maxBytesWhy.empty() ? ", " + m_maxBytesWhy : "") +
                    ")";
    }
    return c;
}

bool ConfinedIOSystem::Exists(const char *path) const
{
    if (!path)
        return false;
    const Check c = check(path);
    // Importers ask after files that may or may not be there (a fallback material library);
    // only a file that is there and refused is worth a line.
    if (!c.problem.empty() && !c.missing)
        note(c.problem);
    return c.problem.empty();
}

Assimp::IOStream *ConfinedIOSystem::Open(const char *path, const char *mode)
{
    if (!path)
        return nullptr;
    if (!mode || std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+')) {
        note(shown(path) + ": the import writes no files");
        return nullptr;
    }
    Check c = check(path);
    if (!c.problem.empty()) {
        // After a material library it could not open, Assimp's OBJ reader looks for
        // MESH.mtl beside the mesh: that this one is missing too says nothing new.
        const bool fallback =
            c.missing && !m_problems.empty() && m_meshPath.size() > 3 &&
            shown(path) == shown(m_meshPath.substr(0, m_meshPath.size() - 3) + "mtl");
        if (!fallback)
            note(c.problem);
        return nullptr;
    }
    // Checked again on what was opened (the name may point elsewhere by now), which is only
    // a regular file, opened without waiting (read_only_file.h).
    platform::FileStatus opened;
    std::unique_ptr<platform::ReadOnlyFile> file =
        platform::ReadOnlyFile::open(resolved(path), opened);
    if (opened.error) {
        note(shown(path) + ": " + opened.error.reason);
        return nullptr;
    }
    c = check(path, &opened);
    if (!c.problem.empty() || !file) {
        note(c.problem.empty() ? shown(path) + ": not a regular file (not a file)" : c.problem);
        return nullptr;
    }
    return new BoundedStream(std::move(file), c.size);
}

void ConfinedIOSystem::Close(Assimp::IOStream *stream)
{
    delete stream;
}

} // namespace lb
