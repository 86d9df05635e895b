#include "work_guard.h"

#include "resident_memory.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace lb {

namespace {
constexpr auto kLookEvery = std::chrono::milliseconds(2);
constexpr long kDefaultProgramMemoryKB = 2L << 20; // 2 GB
} // namespace

long programMemoryKB()
{
    const char *asked = std::getenv("LIGHTBENCH_PROGRAM_MEMORY_MB");
    char *end = nullptr;
    const long megabytes = asked ? std::strtol(asked, &end, 10) : 0;
    return asked && end && *end == '\0' && megabytes > 0 ? megabytes << 10
                                                         : kDefaultProgramMemoryKB;
}

WorkGuard::WorkGuard(long memoryKB, int milliseconds,
                     std::function<void(Limit, long limitKB)> exceeded)
    // A process that already holds much (a big mesh on the command line) keeps room to work:
    // the bound is on what the program adds, not on what the user loaded.
    : m_limitKB(std::max(memoryKB, residentKB() + memoryKB / 2))
{
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(milliseconds);
    m_watch = std::thread([this, deadline, milliseconds, exceeded = std::move(exceeded)] {
        std::unique_lock<std::mutex> lock(m_mutex);
        while (!m_done.wait_for(lock, kLookEvery, [this] { return m_finished; })) {
            if (residentKB() > m_limitKB)
                return exceeded(Limit::Memory, m_limitKB);
            if (milliseconds > 0 && std::chrono::steady_clock::now() > deadline)
                return exceeded(Limit::Time, m_limitKB);
        }
    });
}

WorkGuard::~WorkGuard()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_finished = true;
    }
    m_done.notify_all();
    m_watch.join();
}

const char *memoryText(long kilobytes, char (&buffer)[32])
{
    if (kilobytes >= (1L << 20) && kilobytes % (1L << 20) == 0)
        std::snprintf(buffer, sizeof buffer, "%ld GB", kilobytes >> 20);
    else
        std::snprintf(buffer, sizeof buffer, "%ld MB", kilobytes >> 10);
    return buffer;
}

} // namespace lb
