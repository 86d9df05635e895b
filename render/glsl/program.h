#pragma once
// Building a GLSL program with raw GL calls. QOpenGLShader rewrites the source it is given
// (design.md), so user and built-in shaders alike go to glShaderSource untouched.

#include <QOpenGLExtraFunctions>
#include <QString>

#include <utility>
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

struct ProgramBuild
{
    GLuint program = 0; // 0 when compiling or linking failed
    QString log;        // the driver's messages, stage by stage
    bool ok() const { return program != 0; }
};

// The attribute names bound to each slot (the slides' names first).
const std::vector<std::pair<const char *, AttributeSlot>> &attributeBindings();

// Compiles both stages and links them. The caller owns the returned program.
ProgramBuild buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource);

} // namespace lb
