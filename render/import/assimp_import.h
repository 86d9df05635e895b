#pragma once
// The import helper's work: read a model file with Assimp and write it to the import stream
// (wire.h) as one mesh, every node's meshes with their node transforms applied, centred and
// scaled to fit the view. Runs in lightbench-import only, never in the workbench, so that
// a crash, hang or runaway allocation inside Assimp costs the helper and not the user's work.

#include "wire_writer.h"

#include <string>

namespace lb {

// Returns the helper's exit code: 0, or wire::kExitFailed / kExitOutOfMemory after an
// Error record. `memoryLimitMB` only words the out-of-memory message.
int importToStream(const std::string &path, wire::Writer &out, long long memoryLimitMB);

// Assimp's file extensions, "*.obj;*.ply;..." as Assimp lists them.
std::string assimpExtensions();

} // namespace lb
