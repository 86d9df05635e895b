#include "resident_memory.h"

#include <cstdio>

#include <sys/resource.h>
#include <unistd.h>

namespace lb {

long residentKB()
{
    long pages = 0, resident = 0;
    if (std::FILE *f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
            resident = 0;
        std::fclose(f);
    }
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

long peakResidentKB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss; // KiB on Linux
}

std::uint64_t physicalMemoryBytes()
{
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0)
        return std::uint64_t(pages) * std::uint64_t(pageSize);
    // Where sysconf cannot say (a restricted container): the kernel's own count.
    unsigned long long kilobytes = 0;
    if (std::FILE *f = std::fopen("/proc/meminfo", "r")) {
        char line[256];
        while (std::fgets(line, sizeof line, f))
            if (std::sscanf(line, "MemTotal: %llu kB", &kilobytes) == 1)
                break;
        std::fclose(f);
    }
    return kilobytes * 1024;
}

} // namespace lb
