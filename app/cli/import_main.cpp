// lightbench-import: the helper process that reads one model file with Assimp and writes it
// to stdout as the import stream (render/import/wire.h). The workbench starts it for every
// mesh, so whatever Assimp does with a broken file (crash, hang, runaway allocation) happens
// here, under the memory and CPU limits given on the command line.
//
//   lightbench-import [--memory-limit MB] [--time-limit SECONDS] FILE
//   lightbench-import --formats        Assimp's extensions, "*.obj;*.ply;..."

#include "assimp_import.h"
#include "process_bounds.h"
#include "resident_memory.h"
#include "stream_output.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#ifdef LIGHTBENCH_SANITIZE
#include <sanitizer/asan_interface.h>
#endif
#ifdef LIGHTBENCH_MIMALLOC
#include <mimalloc.h>
#include <new>
#endif

namespace {

int usage()
{
    std::fputs("usage: lightbench-import [--memory-limit MB] [--time-limit SECONDS] FILE\n"
               "       lightbench-import --formats\n",
               stderr);
    return lb::wire::kExitUsage;
}

bool positive(const char *text, long long &value)
{
    char *end = nullptr;
    value = std::strtoll(text, &end, 10);
    return end && *end == '\0' && end != text && value > 0;
}

#ifdef LIGHTBENCH_SANITIZE
// AddressSanitizer reserves terabytes of address space for its shadow memory at start, so
// RLIMIT_AS (and RLIMIT_DATA, which counts those private mappings too) stops it at its next
// mapping ("Failed to mmap"). The sanitizer build bounds the resident memory instead: a thread
// looks every few milliseconds and ends the helper with kExitOutOfMemory, which the window
// turns into the same "out of memory" message; a size ASan refuses outright (an absurd count
// read from a broken file) ends the same way. The two limits count differently (resident
// memory here, with ASan's shadow and quarantine; reserved address space in the normal
// build), and this one is checked, not enforced: it can be passed by what is allocated
// between two looks.
void onSanitizerReport(const char *report)
{
    for (const char *kind : {"allocation-size-too-big", "out-of-memory", "rss-limit-exceeded"})
        if (std::strstr(report, kind))
            std::_Exit(lb::wire::kExitOutOfMemory);
}

} // namespace

// A crash inside Assimp on a broken file is what this process exists to contain: it stays a
// plain crash (the window says the helper crashed), not a sanitizer report about a library
// that is not ours. Our code's memory errors are still reported (they are no signals).
extern "C" const char *__asan_default_options()
{
    return "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0";
}

namespace {

void limitMemory(long long megabytes)
{
    __asan_set_error_report_callback(onSanitizerReport);
    if (!lb::platform::canBoundMemory()) // no resident size to watch in the portable layer
        return;
    std::thread([kilobytes = long(megabytes) * 1024] {
        while (lb::residentKB() <= kilobytes)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        std::_Exit(lb::wire::kExitOutOfMemory);
    }).detach();
}
#else
void limitMemory(long long megabytes)
{
    lb::platform::limitAddressSpace(megabytes << 20); // the portable layer cannot
}
#endif

} // namespace

#ifdef LIGHTBENCH_MIMALLOC
// mimalloc (app/CMakeLists.txt) serves malloc and delete. Its own `new` aborts the process when
// an allocation fails: the library finds the new-handler through a weak symbol that its own
// definition shadows, so no handler ever reaches it. These replacements, found before the
// library's because the executable comes first, throw std::bad_alloc instead, which the
// helper turns into its "out of memory" message.
void *operator new(std::size_t size)
{
    if (void *p = mi_malloc(size))
        return p;
    throw std::bad_alloc();
}

void *operator new[](std::size_t size)
{
    return operator new(size);
}

void *operator new(std::size_t size, std::align_val_t alignment)
{
    if (void *p = mi_malloc_aligned(size, std::size_t(alignment)))
        return p;
    throw std::bad_alloc();
}

void *operator new[](std::size_t size, std::align_val_t alignment)
{
    return operator new(size, alignment);
}
#endif

int main(int argc, char **argv)
{
    // Die with the workbench: a helper must never outlive the window that asked for it.
    lb::platform::dieWithParent();
#ifdef LIGHTBENCH_MIMALLOC
    mi_option_disable(mi_option_show_errors); // failures are the helper's message to give
#endif

    long long memoryMB = 0, seconds = 0;
    const char *path = nullptr;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--formats" && argc == 2) {
            std::printf("%s\n", lb::assimpExtensions().c_str());
            return 0;
        }
        if (arg == "--memory-limit" && i + 1 < argc) {
            if (!positive(argv[++i], memoryMB))
                return usage();
        } else if (arg == "--time-limit" && i + 1 < argc) {
            if (!positive(argv[++i], seconds))
                return usage();
        } else if (!path && !arg.empty() && arg[0] != '-') {
            path = argv[i];
        } else {
            return usage();
        }
    }
    if (!path)
        return usage();
    if (memoryMB > 0)
        limitMemory(memoryMB);
    if (seconds > 0)
        lb::platform::limitCpuSeconds(seconds); // the workbench's clock bounds it too
    lb::platform::disableCoreFiles();

    // The stream has stdout to itself from here on (what an importer prints goes to stderr).
    lb::platform::StreamOutput stream;
    lb::wire::Writer out(stream);
    return lb::importToStream(path, out, memoryMB);
}
