#pragma once
// The trial helper's loop (lightbench-trial): reads messages (trial_wire.h) from `in` until it
// closes, keeps one OpenGL context warm across them, and answers every trial on `out`. Needs a
// QGuiApplication and a display with OpenGL.

#include <cstdio>

namespace lb {

// Returns the process's exit code: 0 when `in` closed, 3 without OpenGL or on a broken stream.
int runTrialServer(std::FILE *in, std::FILE *out);

} // namespace lb
