#include "assimp_import.h"

#include "confined_io_system.h"
#include "fast_mesh_readers.h"
#include "resident_memory.h"
#include "scene_stream.h"

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace lb {

namespace {

using wire::Record;

// Assimp reports its progress here; it goes out as Progress records, at most one per
// percent, and the reading stage takes the first 80 % of the bar.
class Progress : public Assimp::ProgressHandler
{
public:
    explicit Progress(wire::Writer &out) : m_out(out) {}
    bool Update(float percentage) override
    {
        if (percentage >= 0.0f)
            send(0.8f * std::min(percentage, 1.0f), "reading");
        return m_out.ok(); // stop reading when the workbench went away
    }
    void send(float fraction, const char *stage)
    {
        if (fraction < m_last + 0.01f && fraction < 1.0f)
            return;
        m_last = fraction;
        std::string payload(sizeof fraction, '\0');
        std::memcpy(payload.data(), &fraction, sizeof fraction);
        payload += stage;
        m_out.text(Record::Progress, payload);
        m_out.flush();
    }

private:
    wire::Writer &m_out;
    float m_last = -1.0f;
};

std::string outOfMemory(long long limitMB)
{
    std::ostringstream s;
    s << "out of memory: reading this file needs more than the import memory limit (" << limitMB
      << " MB)";
    return s.str();
}

// The most one file read for the mesh may hold: what the workbench allows the mesh file
// itself (ImportLimits::meshByteCap), the memory limit and never more than the machine has.
std::pair<std::uint64_t, std::string> fileByteLimit(long long memoryLimitMB)
{
    const std::uint64_t machine = physicalMemoryBytes();
    const long long machineMB = machine > 0 ? (long long)(machine >> 20) : 8192; // 0: unknown
    if (memoryLimitMB > 0 && memoryLimitMB <= machineMB)
        return {std::uint64_t(memoryLimitMB) << 20, "the import memory limit"};
    return {std::uint64_t(machineMB) << 20, "the machine's memory"};
}

// "the file holds no meshes: only an animation and 2 cameras": what it holds instead.
std::string noMeshes(const aiScene &scene)
{
    std::vector<std::string> held;
    auto count = [&held](unsigned n, const char *one, const char *many) {
        if (n == 1)
            held.push_back(one);
        else if (n > 1)
            held.push_back(std::to_string(n) + " " + many);
    };
    count(scene.mNumAnimations, "an animation", "animations");
    count(scene.mNumCameras, "a camera", "cameras");
    count(scene.mNumLights, "a light", "lights");
    std::string s = "the file holds no meshes";
    for (std::size_t i = 0; i < held.size(); ++i)
        s += (i == 0 ? ": only " : i + 1 == held.size() ? " and " : ", ") + held[i];
    return s;
}

// Which fast reader reads `path`, by its extension; none when the user asked for Assimp only
// (LIGHTBENCH_IMPORT_READER=assimp: for the tests and bench/mesh.sh that compare the two).
const char *fastReaderFor(const std::string &path)
{
    const char *only = std::getenv("LIGHTBENCH_IMPORT_READER");
    if (only && std::strcmp(only, "assimp") == 0)
        return nullptr;
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
    for (char &c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".ply" ? "ply" : ext == ".stl" ? "stl" : nullptr;
}

// The file read by a fast reader and sent, or the file refused; nothing when the fast readers
// decline it (or it cannot be opened: Assimp then says why, as for any file).
std::optional<int> importFast(const std::string &path, wire::Writer &out, long long memoryLimitMB)
{
    const char *reader = fastReaderFor(path);
    if (!reader)
        return std::nullopt;
    const auto [maxBytes, why] = fileByteLimit(memoryLimitMB);
    ConfinedIOSystem files(path, maxBytes, why);
    std::unique_ptr<Assimp::IOStream, std::function<void(Assimp::IOStream *)>> file(
        files.Open(path.c_str(), "rb"), [&files](Assimp::IOStream *s) { files.Close(s); });
    if (!file)
        return std::nullopt;
    Progress progress(out);
    const ReadProgress reading = [&progress, &out](float fraction) {
        progress.send(0.8f * std::min(fraction, 1.0f), "reading");
        return out.ok();
    };
    FastMesh mesh;
    std::string problem;
    const auto start = std::chrono::steady_clock::now();
    const FastRead read = std::strcmp(reader, "ply") == 0
                              ? readPly(*file, mesh, problem, reading)
                              : readBinaryStl(*file, mesh, problem, reading);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    file.reset();
    if (read == FastRead::Declined)
        return std::nullopt;
    if (read == FastRead::Failed)
        return out.fail(problem);
    StreamPart part;
    part.mesh.vertexCount = std::uint32_t(mesh.positions.size() / 3);
    part.mesh.positions = mesh.positions.data();
    part.mesh.normals = mesh.normals.empty() ? nullptr : mesh.normals.data();
    part.mesh.colors = mesh.colors.empty() ? nullptr : mesh.colors.data();
    part.mesh.faceCount = std::uint32_t(mesh.triangles.size() / 3);
    part.mesh.triangles = mesh.triangles.data();
    StreamExtras extras;
    extras.skippedFaces = mesh.skippedFaces;
    extras.reader = reader;
    extras.sendMaterial = [&mesh](std::size_t, wire::Writer &w) {
        w.record(Record::Material, &mesh.material, sizeof mesh.material);
    };
    return writeParts(
        {part}, extras, out,
        [&progress](float fraction, const char *stage) { progress.send(fraction, stage); },
        seconds);
}

} // namespace

int importToStream(const std::string &path, wire::Writer &out, long long memoryLimitMB)
{
    try {
        if (const std::optional<int> fast = importFast(path, out, memoryLimitMB))
            return *fast;
        // Not deleted in the normal build: the helper exits right after this, and the system
        // takes the pages back faster than the importer frees a big scene's million small
        // face arrays. The sanitizer build deletes it, so its leak check has nothing to excuse.
        static std::unique_ptr<Assimp::Importer> owner;
        owner = std::make_unique<Assimp::Importer>();
        Assimp::Importer &importer = *owner;
#ifndef LIGHTBENCH_SANITIZE
        struct Keep
        {
            ~Keep() { owner.release(); }
        } keep;
#endif
        auto *progress = new Progress(out); // the importer owns it
        importer.SetProgressHandler(progress);
        const auto [maxBytes, why] = fileByteLimit(memoryLimitMB);
        auto *files = new ConfinedIOSystem(path, maxBytes, why); // the importer owns it
        importer.SetIOHandler(files);
        // Plain reading plus triangulation: joining identical vertices costs ~6x the time
        // and 5x the memory on big files, and normals are the workbench's job.
        const auto start = std::chrono::steady_clock::now();
        const aiScene *scene = importer.ReadFile(path, aiProcess_Triangulate);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!scene) {
            std::string error = importer.GetErrorString();
            if (error.find("bad_alloc") != std::string::npos)
                return out.fail(outOfMemory(memoryLimitMB), wire::kExitOutOfMemory);
            if (error.empty())
                error = "Assimp could not read the file";
            // The first file refused is the likely reason (the others are mostly Assimp's
            // retries of the same name in other spellings); Assimp's own words follow.
            if (!files->problems().empty())
                error = files->problems().front() + "; Assimp: " + error;
            return out.fail(error);
        }
        if (!scene->mMeshes || scene->mNumMeshes == 0)
            return out.fail(noMeshes(*scene));
        // Assimp did without them (a material library: the default material instead).
        for (const std::string &problem : files->problems())
            out.text(Record::Warning, problem);
        return writeScene(
            *scene, out,
            [progress](float fraction, const char *stage) { progress->send(fraction, stage); },
            seconds);
    } catch (const std::bad_alloc &) {
        return out.fail(outOfMemory(memoryLimitMB), wire::kExitOutOfMemory);
    } catch (const std::exception &e) {
        return out.fail(std::string("import failed: ") + e.what());
    }
}

std::string assimpExtensions()
{
    std::string list;
    Assimp::Importer().GetExtensionList(list);
    return list;
}

} // namespace lb
