#include "allocator_tuning.h"

namespace lb::platform {

bool canTuneAllocator()
{
    return false;
}

// The allocator as it comes: warming may then be undone by the allocator giving memory back.
void keepFreedMemoryInHeap(std::size_t) {}

void giveFreedMemoryBack() {}

// The smallest page of the systems Qt runs on (x86 and ARM; Apple's ARM pages are 16 KiB, so
// warming touches four times the bytes it needs: harmless).
std::size_t pageSize()
{
    return 4096;
}

} // namespace lb::platform
