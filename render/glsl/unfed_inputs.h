#pragma once
// What a linked program reads that nothing feeds and that decides the picture, named on its
// declaration's line with what it could be bound to (bindings.h), so that a pasted shader is
// not a silent black:
// - a matrix no name of the semantic table (semantics.h) matches stays all zeros, and a
//   position multiplied by it draws nothing, with no error from the driver;
// - a vector or number whose name says it is one of the scene's values (uLightPos, u_eyePos,
//   objectColour) but is none of the table's names stays 0 unless its generated control in
//   the Uniforms panel is set: a light at the origin, a black colour.
// The user's "none" for a uniform (a binding) says it is meant to keep its own value.

#include "diagnostics.h"
#include "program_build.h"

#include <QString>

#include <vector>

namespace lb {

// Whether `u` is an input the scene feeds nothing that decides the picture (above).
bool isUnfed(const ActiveUniform &u);

std::vector<Diagnostic> unfedInputWarnings(const std::vector<ActiveUniform> &uniforms,
                                           const QString &vertexSource,
                                           const QString &fragmentSource);

} // namespace lb
