#pragma once
// A program's one route from its sources to drawing, at once: compiled and linked in the
// host, then tried on small frames (program_trial.h) before a frame at the size asked for.
// The command line (--render, --check), grading (the reference, each submission, each known
// mistake) and the trial helper all take it; the window takes it through the helper
// (program_pipeline.h), or in its own context when there is no helper.

#include "program_host.h"
#include "program_trial.h"

#include <functional>
#include <optional>

namespace lb {

struct ProgramVerdict
{
    ProgramBuild build;               // what the compile and link said
    std::optional<TrialResult> trial; // what the trial measured (none: it did not link)
    const Diagnostic *refusal() const
    {
        return trial && trial->refusal ? &*trial->refusal : nullptr;
    }
    bool accepted() const { return build.ok() && !refusal(); }
};

struct ProgramTarget
{
    QSize size;      // the frame the program will draw
    double budgetMs; // at most this per frame there
    TrialSizes sizes = kCommandLineTrial;
};

// The trial of `sources` (program_trial.h) on frames `host` draws, the built-in program's as
// the reference: the one way every route times a program.
TrialResult tryIn(ProgramHost &host, const ProgramSources &sources, const ProgramTarget &target);

// Builds `sources` in `host` and, when they link, calls `linked` (the helper tells the window
// it may build them too) and tries them for `target`. The host draws with them from then on,
// refused or not: the caller stops at a refusal.
ProgramVerdict buildAndTry(ProgramHost &host, const ProgramSources &sources,
                           const ProgramTarget &target,
                           const std::function<void(const ProgramBuild &)> &linked = {});

// The same under a bound on the driver's memory and time (work_guard.h; kProgramLimitMs): a
// program that passes one ends the process, after `pastLimit` is given the refusal on its
// first loop's line, with `exitCode` (the driver never returns to this thread). `linked` says
// the build's warnings before the trial, which is where the bound is most often passed.
ProgramVerdict buildAndTryWithin(ProgramHost &host, const ProgramSources &sources,
                                 const ProgramTarget &target,
                                 const std::function<void(const Diagnostic &)> &pastLimit,
                                 int exitCode,
                                 const std::function<void(const ProgramBuild &)> &linked = {});

} // namespace lb
