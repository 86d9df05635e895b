// lightbench-import: the helper process that reads one model file with Assimp and writes it
// to stdout as the import stream (render/import/wire.h). The workbench starts it for every
// mesh, so whatever Assimp does with a broken file (crash, hang, runaway allocation) happens
// here, under the memory and CPU limits given on the command line.
//
//   lightbench-import [--memory-limit MB] [--time-limit SECONDS] FILE
//   lightbench-import --formats        Assimp's extensions, "*.obj;*.ply;..."

#include "assimp_import.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

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

void limit(int resource, rlim_t value)
{
    rlimit r{value, value};
    if (resource == RLIMIT_CPU)
        r.rlim_max = value + 2; // SIGXCPU first, SIGKILL two seconds later
    setrlimit(resource, &r);
}

} // namespace

int main(int argc, char **argv)
{
    // Die with the workbench: a helper must never outlive the window that asked for it.
    prctl(PR_SET_PDEATHSIG, SIGKILL);

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
        limit(RLIMIT_AS, rlim_t(memoryMB) << 20);
    if (seconds > 0)
        limit(RLIMIT_CPU, rlim_t(seconds));
    limit(RLIMIT_CORE, 0); // a crash costs a message, not a core file

    // The stream gets stdout's descriptor to itself; anything an importer prints on stdout
    // goes to stderr instead of corrupting the stream.
    const int stream = dup(STDOUT_FILENO);
    dup2(STDERR_FILENO, STDOUT_FILENO);
    // A 1 MiB pipe (the unprivileged maximum) instead of 64 KiB: 16 times fewer round trips
    // between the two processes for a big mesh. Fails harmlessly when stdout is no pipe.
    fcntl(stream, F_SETPIPE_SZ, 1 << 20);
    lb::wire::Writer out(stream);
    return lb::importToStream(path, out, memoryMB);
}
