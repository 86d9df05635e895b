// Makes one report of each kind scripts/test --sanitize collects, on purpose: a signed
// overflow (UndefinedBehaviorSanitizer) and a leak (LeakSanitizer). check_reports.sh runs it
// first and fails when its reports are missing: a run whose reports went elsewhere (a changed
// runtime, a wrong folder) must not pass for want of them.
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <thread>

// On a thread of its own, which has ended when LeakSanitizer looks: no register or stack slot
// of a live thread can still hold the pointer (clang's runtime, with UBSan's stack traces on,
// once found it in main()'s when it was lost in a frame of main's thread).
void loseMemory()
{
    std::thread([] {
        void *volatile lost = std::malloc(4242);
        static_cast<char *>(lost)[0] = 1;
    }).join();
}

int main(int argc, char **)
{
    volatile int big = INT_MAX;
    const int overflow = big + argc; // argc is 1: INT_MAX + 1
    loseMemory();
    std::printf("canary: %d\n", overflow);
    return 0;
}
