#pragma once
// Driver compiler and linker logs turned into diagnostics on the user's lines. Known forms:
//   Mesa:              0:13(2): error: `x' undeclared
//   NVIDIA:            0(13) : error C1008: undefined variable "x"
//   AMD, Apple, ANGLE: ERROR: 0:13: 'x' : undeclared identifier   (also WARNING:)
// and lines that name no place at all (most link errors), which get line 0.

#include <QString>

#include <vector>

namespace lb {

enum class ShaderStage { Vertex, Fragment, Link };

struct Diagnostic
{
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    ShaderStage stage = ShaderStage::Link;
    int line = 0;   // 1-based line of the user's source; 0 when the driver names none
    int column = 0; // 1-based; 0 when the driver gives none
    QString message;
};

// `linesAdded`: lines the workbench put before the user's line 1 (see dialect.h).
std::vector<Diagnostic> parseDriverLog(const QString &log, ShaderStage stage, int linesAdded = 0);

QString stageName(ShaderStage stage);

} // namespace lb
