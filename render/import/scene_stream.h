#pragma once
// The second half of the import helper's work: an Assimp scene, as read, written to the import
// stream (wire.h) as one mesh: every node's meshes with their node transforms applied, centred
// and scaled to fit the view, then the largest mesh's material and diffuse texture, figures
// about the load (Info) and the End record. Plain C++: the helper only.

#include "wire_writer.h"

#include <functional>

struct aiScene;

namespace lb {

// Progress as the stream's Progress records carry it: a fraction in [0, 1] and the stage.
using ImportProgress = std::function<void(float fraction, const char *stage)>;

// Vertices whose transformed position is not finite (NaN, +-inf, or a finite value that the
// node transform carries past float's range) are dropped, with every triangle that uses one:
// a triangle cannot be drawn, lit or framed with such a corner. The Info record counts them
// ("nonFinite", "droppedTriangles"). Non-finite normals make the file's normals unusable
// (counted as "nonFiniteNormals"); the workbench generates normals then.
// Returns the helper's exit code: 0, or wire::kExitFailed after an Error record.
int writeScene(const aiScene &scene, wire::Writer &out, const ImportProgress &progress,
               double readSeconds);

} // namespace lb
