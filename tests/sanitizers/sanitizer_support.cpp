// Linked into every executable of the sanitizer build (CMakeLists.txt, LIGHTBENCH_SANITIZE):
// what makes every report of every process reach scripts/test --sanitize.

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

extern "C" {

// Qt unloads its plugins and the libraries it opened itself (libdbus, the xcb platform, the
// GLX vendor library and Mesa's driver) before the process exits, and LeakSanitizer looks for
// leaks after that: a leak inside an unloaded library is reported as "<unknown module>", which
// no suppression can name. A dlclose() that keeps every library loaded keeps their names in
// the reports, so lsan.supp can name the third-party ones and our own stay visible.
// The executable's definition comes first in symbol lookup, ahead of the C library's and the
// sanitizer's own.
int dlclose(void *)
{
    return 0;
}

// GCC's UndefinedBehaviorSanitizer runtime (libubsan) ignores log_path when AddressSanitizer
// is linked too, and prints only on stderr, which the helpers' parents read and drop. It calls
// this hook for every report (a weak definition in libubsan; ours comes first): the report is
// appended to LIGHTBENCH_SANITIZER_REPORTS/ubsan.EXE.PID, where scripts/test looks.
void __ubsan_get_current_report_data(const char **kind, const char **message, const char **file,
                                     unsigned *line, unsigned *column, char **address);

void __ubsan_on_report()
{
    const char *dir = std::getenv("LIGHTBENCH_SANITIZER_REPORTS");
    if (!dir || !*dir)
        return;
    const char *kind = "", *message = "", *file = "";
    unsigned line = 0, column = 0;
    char *address = nullptr;
    __ubsan_get_current_report_data(&kind, &message, &file, &line, &column, &address);
    char path[4096];
    std::snprintf(path, sizeof path, "%s/ubsan.%s.%ld", dir, program_invocation_short_name,
                  long(getpid()));
    if (FILE *f = std::fopen(path, "a")) {
        std::fprintf(f, "%s:%u:%u: runtime error: %s [%s]\n", file ? file : "?", line, column,
                     message ? message : "", kind ? kind : "");
        std::fclose(f);
    }
}

} // extern "C"
