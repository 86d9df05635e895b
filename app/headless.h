#pragma once
// --render, --probe and --bench-frames: one offscreen frame (or many), no window.

#include "command_line.h"
#include "probe.h"

#include <QImage>
#include <QJsonObject>

namespace lb {

// Returns the process exit code: 0 done, 1 when OpenGL or writing the file failed.
int runHeadless(const CommandLine &commandLine, const Scene &scene);

// The probe's JSON for one pixel: what the GPU drew beside what the reference says.
QJsonObject probeJson(const ProbeResult &probe, const QImage &frame, QPoint pixel,
                      const Scene &scene);

} // namespace lb
