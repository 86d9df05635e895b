#pragma once
// Bounds a stretch of work that runs a stranger's input inside a library we cannot stop: the
// GL driver compiling and drawing a user's program (its preprocessor once grew to 24 GB on a
// 946-byte shader), a submission's frames. A thread looks at the process's resident memory
// every 2 ms and at the clock; past either limit it calls `exceeded` there, on its own thread,
// while the stuck thread is still inside the driver: `exceeded` says why (a message, a
// grading report) and must end the process (std::_Exit), as nothing can unwind the driver.
// Checked, not enforced: what is allocated between two looks passes (a bomb grows by a few
// hundred MB/s, so about a megabyte). Unlike RLIMIT_AS it leaves the address space alone, which
// GPU drivers (and AddressSanitizer) reserve by the terabyte.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace lb {

// The memory a user's program may make the driver take (WorkGuard's `memoryKB`): 2 GB, or
// $LIGHTBENCH_PROGRAM_MEMORY_MB (a machine with little memory; the tests' small bound).
long programMemoryKB();

class WorkGuard
{
public:
    enum class Limit { Memory, Time };
    // Resident memory over max(`memoryKB`, what the process holds now + `memoryKB` / 2), or
    // `milliseconds` passed (0: no time limit). `exceeded` gets which, and the memory limit.
    WorkGuard(long memoryKB, int milliseconds, std::function<void(Limit, long limitKB)> exceeded);
    ~WorkGuard(); // the work is done: disarmed
    WorkGuard(const WorkGuard &) = delete;
    WorkGuard &operator=(const WorkGuard &) = delete;

private:
    long m_limitKB;
    std::mutex m_mutex;
    std::condition_variable m_done;
    bool m_finished = false;
    std::thread m_watch;
};

// "2 GB", "512 MB"
const char *memoryText(long kilobytes, char (&buffer)[32]);

} // namespace lb
