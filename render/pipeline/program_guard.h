#pragma once
// The bounds on a user's program where the driver runs in this process (the command line, the
// grading child: program_route.h): its compile, link and trial frames run under a WorkGuard
// (work_guard.h) with these limits, and a program that passes one is refused with this
// message, on its first loop's line.

#include "diagnostics.h"
#include "work_guard.h"

namespace lb {

// Compile, link and the trial's small frames together: the command line answers within 20 s
// whatever the program (25,000 lines of sin() took the driver 4.7 s to compile).
constexpr int kProgramLimitMs = 15000;

Diagnostic guardRefusal(WorkGuard::Limit limit, long limitKB, const QString &vertex,
                        const QString &fragment);

} // namespace lb
