#include "process_bounds.h"

#include <csignal>
#include <sys/prctl.h>
#include <sys/resource.h>

namespace lb::platform {

namespace {

bool limit(int resource, rlim_t soft, rlim_t hard)
{
    const rlimit r{soft, hard};
    return setrlimit(resource, &r) == 0;
}

} // namespace

const char *name()
{
    return "linux";
}

bool canBoundMemory()
{
    return true;
}

bool dieWithParent()
{
    return prctl(PR_SET_PDEATHSIG, SIGKILL) == 0;
}

bool limitAddressSpace(long long bytes)
{
    // RLIMIT_DATA counts the private mappings too since Linux 4.7; the address space is what
    // every allocation path (brk, mmap, a driver's own) has to pass.
    return limit(RLIMIT_AS, rlim_t(bytes), rlim_t(bytes));
}

bool limitCpuSeconds(long long seconds)
{
    return limit(RLIMIT_CPU, rlim_t(seconds), rlim_t(seconds) + 2); // SIGXCPU, then SIGKILL
}

void disableCoreFiles()
{
    limit(RLIMIT_CORE, 0, 0);
}

} // namespace lb::platform
