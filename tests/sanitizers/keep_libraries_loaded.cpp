// Linked into every executable of the sanitizer build (CMakeLists.txt, LIGHTBENCH_SANITIZE).
//
// Qt unloads its plugins and the libraries it opened itself (libdbus, the xcb platform, the
// GLX vendor library and Mesa's driver) before the process exits, and LeakSanitizer looks for
// leaks after that: a leak inside an unloaded library is reported as "<unknown module>", which
// no suppression can name. A dlclose() that keeps every library loaded keeps their names in
// the reports, so lsan.supp can name the third-party ones and our own stay visible.
// The executable's definition comes first in symbol lookup, ahead of the C library's and the
// sanitizer's own.

extern "C" int dlclose(void *)
{
    return 0;
}
