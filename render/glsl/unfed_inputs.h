#pragma once
// What a linked program reads that nothing feeds and that decides the picture: a matrix no
// name of the semantic table (semantics.h) matches stays all zeros, and a position multiplied
// by it draws nothing, with no error from the driver. Named on its declaration's line with
// the names the scene would feed, so that a pasted shader is not a silent black.

#include "diagnostics.h"
#include "program_build.h"

#include <QString>

#include <vector>

namespace lb {

std::vector<Diagnostic> unfedInputWarnings(const std::vector<ActiveUniform> &uniforms,
                                           const QString &vertexSource,
                                           const QString &fragmentSource);

} // namespace lb
