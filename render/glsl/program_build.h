#pragma once
// What building a program said, without OpenGL: the diagnostics on the user's lines and the
// linked program's active uniforms as GLSL declares them. The GL side (render/gl/program.h)
// adds the one owner of the program object; widgets, the command line and tests see this.

#include "diagnostics.h"
#include "semantics.h"

#include <QString>

#include <optional>
#include <vector>

namespace lb {

// A uniform's declared type in GLSL terms: the scalar kind and how wide it is.
enum class UniformKind { Float, Int, Bool, Matrix, Sampler, Other };

// The shape the semantic table matches a uniform of `kind` by (semantics.h).
inline UniformShape shapeOf(UniformKind kind)
{
    switch (kind) {
    case UniformKind::Matrix:
        return UniformShape::Matrix;
    case UniformKind::Sampler:
        return UniformShape::Sampler;
    case UniformKind::Other:
        return UniformShape::Any;
    default:
        return UniformShape::Number;
    }
}

struct ActiveUniform
{
    QString name; // without "[0]"
    UniformKind kind = UniformKind::Other;
    int width = 1; // 1 to 4 for scalars and vectors (vec3: 3); 2 to 4 for square matrices
    int size = 1;  // array length
    int location = -1;
    std::optional<Semantic> semantic; // what the scene feeds it (none: its own value)
    // What its name alone gives (the semantic table's), and whether `semantic` is the user's
    // choice instead (bindings.h).
    std::optional<Semantic> byName;
    bool bound = false;
    // The value right after linking (its initializer, or 0), for the generated controls.
    std::vector<float> initial;

    // How many numbers a generated control edits: 1 to 4 for float/int/bool and vectors;
    // 0 for what gets no control (matrices, samplers, arrays).
    int components() const;
    bool isInteger() const { return kind == UniformKind::Int || kind == UniformKind::Bool; }
    bool isBool() const { return kind == UniformKind::Bool; }
    // Its type as GLSL writes it: float, ivec3, mat4, sampler2D ("?" for another).
    QString glslType() const;
};

// An active vertex input and the location it was linked at (program.h's slots: 0 positions,
// 1 normals, 2 texture coordinates, 3 vertex colours; another location is fed nothing).
struct ActiveInput
{
    QString name;
    int location = -1;
};

struct ProgramBuild
{
    bool linked = false; // compiled, linked and able to draw the object
    std::vector<Diagnostic> diagnostics;
    std::vector<ActiveUniform> uniforms; // the linked program's active uniforms
    std::vector<ActiveInput> attributes; // and its active vertex inputs
    bool ok() const { return linked; }
    bool hasErrors() const;
    const Diagnostic *firstError() const; // the first error, or none
    QString log() const;                  // the diagnostics as text, one per line
    bool reads(Semantic semantic) const;
    // Whether the program takes the panel's light position (in any frame); one that does not
    // hard-codes its light, and the window draws no marker where its light is not.
    bool readsLightPosition() const
    {
        return reads(Semantic::LightPosition) || reads(Semantic::LightPositionEye) ||
               reads(Semantic::LightPositionWorld) || reads(Semantic::LightDirectionWorld) ||
               reads(Semantic::ReverseLightDirection);
    }
};

} // namespace lb
