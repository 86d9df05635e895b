#pragma once
// This process's memory and the machine's, as the system counts them (Linux: /proc,
// getrusage, sysconf). 0 where they cannot be read (the portable layer): callers treat 0 as
// "unknown", never as "none used".

#include <cstdint>

namespace lb {

// Resident memory now, in KiB.
long residentKB();

// The most resident memory this process has held, in KiB.
long peakResidentKB();

// The machine's physical memory in bytes, 0 if unknown.
std::uint64_t physicalMemoryBytes();

} // namespace lb
