#pragma once
// The headless run's heap, faulted in while the import helper reads. Once OpenGL is set up the
// main thread has nothing to do until the mesh arrives; after that, every first touch of a
// page (zeroed by the kernel, 4 KB at a time) of the mesh's arrays, normal generation's and
// the driver's copies lies on the path from the file to the PNG: ~26 k page faults for a
// 1M-triangle mesh (40.5 k in all against 14.7 k for the default sphere). This spends the
// idle time touching the heap those arrays will be put in, in steps between the helper's
// messages, and hands it back to the allocator (not to the system) when Assimp is done reading
// (the helper's "converting" stage) or the import ends; giveBack() returns what is free then
// to the system, once the arrays it was warmed for are freed.

#include <QTimer>

#include <cstddef>

namespace lb {

class HeapWarmer
{
public:
    // Up to `bytes` (at most 508 MB); nothing at all for 0. Also keeps big allocations in the heap
    // and what is freed there, for the rest of the process: glibc otherwise maps each array over
    // 128 KB on its own and unmaps it when freed, so the next stage faults in new pages. Fit for a
    // short run, not for the window.
    explicit HeapWarmer(std::size_t bytes);
    ~HeapWarmer();
    HeapWarmer(const HeapWarmer &) = delete;
    HeapWarmer &operator=(const HeapWarmer &) = delete;

    // Stops and frees what was touched, which the next allocations reuse.
    void stop();
    // Stops, and gives what is free in the heap back to the system: for when the arrays it
    // was warmed for are freed and what comes next needs less (a headless run's frame, once
    // the mesh is in the driver's buffers). Nothing when nothing was warmed.
    void giveBack();
    std::size_t warmedBytes() const { return m_warmed; }

private:
    void step();

    char *m_block = nullptr; // one block, so that what it frees is one piece of the heap
    std::size_t m_size = 0;
    std::size_t m_warmed = 0;
    bool m_tuned = false; // the allocator keeps freed memory (keepFreedMemoryInHeap)
    QTimer m_timer;
};

} // namespace lb
