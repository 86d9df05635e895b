#pragma once
// Every file Assimp opens for one mesh goes through here (Importer::SetIOHandler): the mesh
// itself and whatever it refers to (an OBJ's material library, a glTF's buffers, includes).
// A mesh comes from a stranger, so each file is checked before a byte of it is read: a regular
// file (a FIFO would hang the import, a device never ends), within a size limit (Assimp reads
// most files whole), and, for the files the mesh refers to, inside the mesh's folder tree
// after links are resolved (a glTF buffer "../../../etc/passwd" would be drawn as vertices).
// What is refused is kept as a line for the user; Assimp decides whether it can do without
// the file (a material library: yes; a glTF buffer: no). Plain C++ and the platform room's
// file_status.h and read_only_file.h: helper only.

#include <assimp/DefaultIOSystem.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lb {

namespace platform {
struct FileStatus;
}

class ConfinedIOSystem : public Assimp::DefaultIOSystem
{
public:
    // `meshPath`: the file the user opened; its folder (links resolved) is the tree side
    // files must stay in. `maxBytes`: the most any one file may hold (the mesh file's own
    // limit, the import memory limit); `maxBytesWhy` says where it comes from.
    ConfinedIOSystem(const std::string &meshPath, std::uint64_t maxBytes, std::string maxBytesWhy);

    bool Exists(const char *path) const override;
    Assimp::IOStream *Open(const char *path, const char *mode = "rb") override;
    void Close(Assimp::IOStream *stream) override;

    // One line per file refused or not found when Assimp asked to read it, in the order met:
    // "materials.mtl: not a regular file (a FIFO)". Names are as the mesh gives them,
    // relative to its folder.
    const std::vector<std::string> &problems() const { return m_problems; }

    // The largest material library (.mtl) accepted: it is a few lines per material, and
    // Assimp reads it whole and parses it into more memory than it takes on disk.
    static constexpr std::uint64_t kMaxMaterialLibraryBytes = 64ull << 20;

private:
    struct Check
    {
        std::string problem; // empty: the file may be read
        bool missing = false;
        std::uint64_t size = 0;
    };
    // Checks `path` (no file is opened); `opened`: checks the status of the file opened
    // instead of the name's.
    Check check(const std::string &path, const platform::FileStatus *opened = nullptr) const;
    void note(const std::string &problem) const;
    std::string shown(const std::string &path) const;

    std::string m_meshPath;
    std::string m_meshResolved; // the mesh file itself, links resolved
    std::string m_meshFolder;   // as given, with a trailing '/'
    std::string m_root;         // the folder, links resolved, with a trailing '/'
    std::uint64_t m_maxBytes;
    std::string m_maxBytesWhy;
    mutable std::vector<std::string> m_problems; // Exists() is const in Assimp's interface
};

} // namespace lb
