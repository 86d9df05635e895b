#include "process_bounds.h"

// Standard C++ has no process limits. What a platform of its own would use: a job object
// on Windows (JOB_OBJECT_LIMIT_PROCESS_MEMORY, KILL_ON_JOB_CLOSE), setrlimit on macOS
// (RLIMIT_AS is not enforced there; RLIMIT_DATA is) with a kqueue watch for the parent.

namespace lb::platform {

const char *name()
{
    return "portable";
}

bool canBoundMemory()
{
    return false;
}

bool dieWithParent()
{
    return false;
}

bool limitAddressSpace(long long)
{
    return false;
}

bool limitCpuSeconds(long long)
{
    return false;
}

void disableCoreFiles() {}

} // namespace lb::platform
