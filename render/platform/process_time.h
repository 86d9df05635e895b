#pragma once
// The processor time this process has used, all its threads together (Linux: clock_gettime's
// CLOCK_PROCESS_CPUTIME_ID). A software rasterizer (Mesa's llvmpipe) draws a frame on this
// process's threads: their processor time is the frame's work, which other programs on the
// same cores do not stretch as they stretch the wall clock (program_trial.h).

namespace lb {

// Milliseconds of processor time since some fixed point; negative where it cannot be read
// (then callers use the wall clock).
double processorTimeMs();

} // namespace lb
