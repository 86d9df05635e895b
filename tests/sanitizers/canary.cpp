// Makes one report of each kind scripts/test --sanitize collects, on purpose: a signed
// overflow (UndefinedBehaviorSanitizer) and a leak (LeakSanitizer). check_reports.sh runs it
// first and fails when its reports are missing: a run whose reports went elsewhere (a changed
// runtime, a wrong folder) must not pass for want of them.
#include <climits>
#include <cstdio>
#include <cstdlib>

// Its own frame, so no register or stack slot of main() still holds the pointer at exit.
__attribute__((noinline)) void loseMemory()
{
    void *volatile lost = std::malloc(4242);
    static_cast<char *>(lost)[0] = 1;
}

int main(int argc, char **)
{
    volatile int big = INT_MAX;
    const int overflow = big + argc; // argc is 1: INT_MAX + 1
    loseMemory();
    std::printf("canary: %d\n", overflow);
    return 0;
}
