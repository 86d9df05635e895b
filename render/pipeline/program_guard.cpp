#include "program_guard.h"

#include "program_trial.h"

#include <QCoreApplication>

namespace lb {

Diagnostic guardRefusal(WorkGuard::Limit limit, long limitKB, const QString &vertex,
                        const QString &fragment)
{
    char memory[32];
    return refusalAt(
        vertex, fragment,
        limit == WorkGuard::Limit::Memory
            ? QCoreApplication::translate(
                  "lb::ProgramGuard",
                  "the driver ran out of memory compiling or drawing this program (limit %1): a "
                  "macro that doubles itself, or a program too big for it?")
                  .arg(memoryText(limitKB, memory))
            : QCoreApplication::translate(
                  "lb::ProgramGuard",
                  "compiling this program and drawing it on small frames took more than %1: an "
                  "endless or very long loop, or a program too big for the driver?")
                  .arg(durationText(kProgramLimitMs)));
}

} // namespace lb
