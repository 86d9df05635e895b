#pragma once
// Building a GLSL program with raw GL calls. QOpenGLShader rewrites the source it is given
// (design.md), so user and built-in shaders alike go to glShaderSource as prepareSource()
// leaves them (dialect.h), and the driver's messages come back on the user's lines.

#include "diagnostics.h"
#include "semantics.h"

#include <QOpenGLExtraFunctions>
#include <QString>

#include <optional>
#include <vector>

namespace lb {

// Fixed attribute slots, bound by name before linking so every program reads the renderer's
// buffers the same way.
enum AttributeSlot : GLuint {
    kPositionSlot = 0,
    kNormalSlot = 1,
    kColorSlot = 2,
    kTexCoordSlot = 3
};

struct ActiveUniform
{
    QString name; // without "[0]"
    GLenum type = 0;
    GLint size = 1; // array length
    GLint location = -1;
    std::optional<Semantic> semantic;
    // The value right after linking (its initializer, or 0), for the generated controls.
    std::vector<float> initial;

    // How many numbers a generated control edits: 1 to 4 for float/int/bool and vectors;
    // 0 for what gets no control (matrices, samplers, arrays).
    int components() const;
    bool isInteger() const; // int, ivecN, bool, bvecN
};

struct ProgramBuild
{
    GLuint program = 0; // 0 when compiling or linking failed; the caller owns it otherwise
    std::vector<Diagnostic> diagnostics;
    std::vector<ActiveUniform> uniforms; // the linked program's active uniforms
    bool ok() const { return program != 0; }
    bool hasErrors() const;
    QString log() const; // the diagnostics as text, one per line
};

// The names bound to each slot: the slides', the exercise's and common generic ones.
struct AttributeBinding
{
    const char *name;
    AttributeSlot slot;
};
const std::vector<AttributeBinding> &attributeBindings();

// The bare cost of building: glShaderSource, glCompileShader (both stages), glLinkProgram,
// nothing else; for the editor's benchmark (bench/edit.sh). Milliseconds.
// With `draw`, also one draw call with the new program and a glFinish: drivers such as
// llvmpipe generate the machine code at the first draw, not at link time.
double rawBuildMilliseconds(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                            const QString &fragmentSource, bool draw = false);

// Compiles both stages and links them.
ProgramBuild buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource);

} // namespace lb
