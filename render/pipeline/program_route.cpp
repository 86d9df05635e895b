#include "program_route.h"

#include "program_guard.h"
#include "work_guard.h"

#include <cstdio>
#include <cstdlib>

namespace lb {

TrialResult tryIn(ProgramHost &host, const ProgramSources &sources, const ProgramTarget &target)
{
    return tryProgram(
        sources.vertex, sources.fragment, target.size, target.budgetMs, target.sizes,
        [&](QSize pixels) { return host.timeFrame(pixels); },
        [&](QSize pixels) { return host.timeBuiltInFrame(pixels); });
}

ProgramVerdict buildAndTry(ProgramHost &host, const ProgramSources &sources,
                           const ProgramTarget &target,
                           const std::function<void(const ProgramBuild &)> &linked)
{
    ProgramVerdict verdict;
    verdict.build = host.use(sources);
    if (!verdict.build.ok())
        return verdict;
    if (linked)
        linked(verdict.build);
    verdict.trial = tryIn(host, sources, target);
    return verdict;
}

ProgramVerdict buildAndTryWithin(ProgramHost &host, const ProgramSources &sources,
                                 const ProgramTarget &target,
                                 const std::function<void(const Diagnostic &)> &pastLimit,
                                 int exitCode,
                                 const std::function<void(const ProgramBuild &)> &linked)
{
    const WorkGuard guard(
        programMemoryKB(), kProgramLimitMs, [&](WorkGuard::Limit limit, long limitKB) {
            pastLimit(guardRefusal(limit, limitKB, sources.vertex, sources.fragment));
            std::fflush(nullptr);
            std::_Exit(exitCode);
        });
    return buildAndTry(host, sources, target, linked);
}

} // namespace lb
