#pragma once
// --render, --probe and --bench-frames: one offscreen frame (or many), no window.

#include "command_line.h"
#include "diagnostics.h"
#include "probe.h"

#include <QImage>
#include <QJsonObject>

namespace lb {

// Returns the process exit code: 0 done; 1 when OpenGL, the user's program (--vertex,
// --fragment) or writing the file failed, and for --check when the program does not link.
int runHeadless(const CommandLine &commandLine, const Scene &scene);

// FILE:LINE:COLUMN: error|warning: message (column 0 when the driver gives none).
QString formatDiagnostic(const Diagnostic &diagnostic, const CommandLine &commandLine);

// The probe's JSON for one pixel: what the GPU drew there (the surface, read before any
// overlay) beside what the reference says.
QJsonObject probeJson(const ProbeResult &probe, const glm::ivec3 &gpu, QPoint pixel,
                      const Scene &scene);

} // namespace lb
