#pragma once
// Which GLSL a source is written in, and what the driver is handed. A source without
// #version is a WebGL 1 shader (GLSL ES 1.00), as browsers treat it: it gets "#version 100"
// in front, which core-profile drivers with ARB_ES2_compatibility accept (design.md), so
// attribute, varying, gl_FragColor, texture2D and precision work as pasted. Anything with
// #version runs as written.

#include "diagnostics.h"

#include <QString>

namespace lb {

// Longer sources are refused with a message rather than handed to the driver, and scene
// files holding longer ones are not read.
constexpr int kMaxSourceCharacters = 1024 * 1024;

enum class Dialect {
    WebGL1Implicit,   // no #version: "#version 100" in front
    Versioned,        // as written
    WebGL1Translated, // no #version or "#version 100", rewritten as GLSL 3.30 core
    LegacyTranslated, // GLSL 1.10 to 1.30 with fixed-function built-ins, as GLSL 3.30 core
};

struct PreparedSource
{
    QString text;       // what glShaderSource gets
    int linesAdded = 0; // lines put before the user's line 1; diagnostics subtract them
    Dialect dialect = Dialect::Versioned;
    QString version; // "100", "300 es", "330 core"...; "100" for the implicit dialect
};

PreparedSource prepareSource(const QString &source);
// The same, translated (webgl1_translation.h) when `translateWebGl1` and the source is WebGL 1
// (no #version, or "#version 100").
PreparedSource prepareSource(const QString &source, ShaderStage stage, bool translateWebGl1);
// The same for one stage of a program that uses the fixed-function pipeline's built-ins
// (legacyProgram()): translated to GLSL 3.30 with them declared (legacy_builtins.h).
PreparedSource prepareLegacySource(const QString &source, ShaderStage stage);

// Whether a program is desktop GLSL of the fixed-function era: either stage uses its built-ins
// (gl_Vertex, gl_ModelViewMatrix, gl_LightSource...) and each has no #version, or 110, 120 or
// 130. Both stages are then translated, so that they link with each other.
bool legacyProgram(const QString &vertexSource, const QString &fragmentSource);

// The source with comments blanked out (line structure kept), for simple textual checks.
QString withoutComments(const QString &source);

// Whether a fragment shader writes a colour at all: gl_FragColor, gl_FragData or an out
// variable. A program without one links, but draws an undefined colour.
bool writesFragmentColour(const QString &fragmentSource);

} // namespace lb
