#pragma once
// Whether an object shows anything in the view, and if not, why: a file that loads and draws
// nothing (a flat polygon seen edge-on, a mesh behind the camera) says so instead of leaving
// an empty frame without a word.

#include "mesh.h"
#include "scene.h"

#include <QSize>
#include <QString>

namespace lb {

// What is wrong with what object `index` of `scene`, drawing `mesh` in a view of `size`
// pixels, shows, said after the object's name: "draws nothing in view: it is flat (in the YZ
// plane) and seen edge-on: ...", "draws nothing in view: it lies outside the view", "is seen
// from behind: every face in view turns its back to the camera, ..."; empty when front faces
// cover a pixel or more, or the object is hidden. Stops at the first pixel of front faces: a
// mesh in view costs a few of its triangles.
QString viewProblem(const Scene &scene, int index, const Mesh &mesh, QSize size);

} // namespace lb
