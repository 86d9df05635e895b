#pragma once
// Asks the C library's allocator to keep what is freed for the next allocation and to serve
// big arrays from its heap (Linux: glibc's mallopt), so that a heap warmed ahead of a big
// mesh stays warm (render/import/heap_warmer.h). Does nothing where no such tuning exists.

#include <cstddef>

namespace lb::platform {

// Whether keepFreedMemoryInHeap() does anything here (false in the portable layer).
bool canTuneAllocator();

// Allocations up to `bigBlockBytes` come from the heap, and freed memory stays in it.
void keepFreedMemoryInHeap(std::size_t bigBlockBytes);

// Gives the pages of what is free in the heap back to the system (Linux: malloc_trim), for a
// run whose big arrays are freed and whose next stage needs less: they would otherwise stay
// resident with keepFreedMemoryInHeap().
void giveFreedMemoryBack();

// The size of a memory page: touching one byte in each makes a block resident.
std::size_t pageSize();

} // namespace lb::platform
