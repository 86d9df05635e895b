#include "heap_warmer.h"

#include "allocator_tuning.h"

#include <algorithm>
#include <cstdlib>

namespace lb {

namespace {

// One step touches this much (~2 ms) before the event loop reads the helper's stream again.
constexpr std::size_t kStepBytes = 4u << 20;
// Allocations up to this size come from the heap; bigger ones are mapped on their own (and
// unmapped when freed, so a block that big would warm nothing).
constexpr int kMmapThreshold = 512 << 20;

} // namespace

HeapWarmer::HeapWarmer(std::size_t bytes)
{
    if (bytes == 0)
        return; // no mesh file: the allocator as it comes
    platform::keepFreedMemoryInHeap(kMmapThreshold);
    m_tuned = true;
    bytes = std::min(bytes, std::size_t(kMmapThreshold) - kStepBytes);
    // Taken whole at once (no page is touched yet), so that allocations made between the
    // steps (the stream's buffers, Qt's events) land beside it, not inside it.
    m_block = static_cast<char *>(std::malloc(bytes));
    m_size = m_block ? bytes : 0;
    m_timer.setInterval(0);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { step(); });
    if (m_block)
        m_timer.start();
}

HeapWarmer::~HeapWarmer()
{
    stop();
}

void HeapWarmer::step()
{
    const std::size_t end = std::min(m_size, m_warmed + kStepBytes);
    const std::size_t page = platform::pageSize();
    volatile char *block = m_block;
    for (std::size_t at = m_warmed; at < end; at += page)
        block[at] = 0;
    m_warmed = end;
    if (m_warmed == m_size)
        m_timer.stop();
}

void HeapWarmer::stop()
{
    m_timer.stop();
    std::free(m_block); // to the heap, which keeps it (M_TRIM_THRESHOLD)
    m_block = nullptr;
    m_size = 0;
}

void HeapWarmer::giveBack()
{
    stop();
    if (m_tuned)
        platform::giveFreedMemoryBack();
}

} // namespace lb
