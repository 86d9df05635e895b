#include "resident_memory.h"

// Standard C++ and Qt cannot read a process's memory. What a platform of its own would use:
// GetProcessMemoryInfo and GlobalMemoryStatusEx on Windows; task_info(MACH_TASK_BASIC_INFO)
// and sysctl(HW_MEMSIZE) on macOS.

namespace lb {

long residentKB()
{
    return 0;
}

long peakResidentKB()
{
    return 0;
}

std::uint64_t physicalMemoryBytes()
{
    return 0;
}

} // namespace lb
