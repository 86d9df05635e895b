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

// A vertex input whose name says one mesh array (`slotOfName`: program.h's slots, 0 positions,
// 1 normals, 2 texture coordinates, 3 colours) but that its layout(location = N) puts at
// another: it reads that other array (opengl-tutorial.org's normal at 2 reads the texture
// coordinates). Named on its declaration's line.
struct PlacedInput
{
    QString name;
    int location = -1;
    int slotOfName = -1;
};
std::vector<Diagnostic> misplacedInputWarnings(const std::vector<PlacedInput> &inputs,
                                               const QString &vertexSource);

// Whether `u` is an input the scene feeds nothing that decides the picture (above).
bool isUnfed(const ActiveUniform &u);

std::vector<Diagnostic> unfedInputWarnings(const std::vector<ActiveUniform> &uniforms,
                                           const QString &vertexSource,
                                           const QString &fragmentSource);

} // namespace lb
