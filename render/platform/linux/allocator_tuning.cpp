#include "allocator_tuning.h"

#include <malloc.h>
#include <unistd.h>

namespace lb::platform {

bool canTuneAllocator()
{
    return true;
}

void keepFreedMemoryInHeap(std::size_t bigBlockBytes)
{
    mallopt(M_MMAP_THRESHOLD, int(bigBlockBytes)); // big arrays from the heap, not mapped alone
    mallopt(M_TRIM_THRESHOLD, 1 << 30);            // what is freed stays for the next stage
    mallopt(M_TOP_PAD, 64 << 20);                  // the heap grows in few steps
}

void giveFreedMemoryBack()
{
    malloc_trim(0);
}

std::size_t pageSize()
{
    const long size = sysconf(_SC_PAGESIZE);
    return size > 0 ? std::size_t(size) : 4096;
}

} // namespace lb::platform
