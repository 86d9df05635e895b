#pragma once
// The bounds a process puts on itself before it touches a stranger's input (the import and
// trial helpers, a submission's child): die with its parent, a memory limit, a CPU-time limit,
// no core file. Linux does them all (prctl, setrlimit); the portable layer can do none and
// says so, and its helpers are bounded in time only, by the parent that kills them.

namespace lb::platform {

// "linux" or "portable": which implementation this build has (tests print it).
const char *name();

// Whether limitAddressSpace() and residentKB() work here, so that a helper's memory can be
// bounded. False in the portable layer: tests of memory refusals skip there.
bool canBoundMemory();

// This process is killed when the process that started it ends (Linux: PR_SET_PDEATHSIG);
// false where it cannot be arranged (the helper then ends when its input closes, or when
// the parent's time limit kills it).
bool dieWithParent();

// At most `bytes` of address space (and of data) for this process from now on: an
// allocation past it fails (std::bad_alloc, a null malloc). False where it cannot be set.
bool limitAddressSpace(long long bytes);

// At most `seconds` of CPU time: the process gets SIGXCPU then, and SIGKILL two seconds
// later. False where it cannot be set.
bool limitCpuSeconds(long long seconds);

// A crash costs a message, not a core file.
void disableCoreFiles();

} // namespace lb::platform
