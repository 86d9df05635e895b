#pragma once
// --plot KIND: the model's curve for the command line's scene into --render (PNG, or SVG for
// a name ending in .svg) and its samples into --plot-data (CSV), for slides and handouts.

#include "command_line.h"
#include "probe.h"

namespace lb {

// Writes what `cl` asks for, the probe's point marked where `probe` hit one. Returns the exit
// code: 0, or 1 with a line on stderr naming the file that could not be written.
int writePlotOutputs(const CommandLine &cl, const Scene &scene, const ProbeResult *probe);

} // namespace lb
