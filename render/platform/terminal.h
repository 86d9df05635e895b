#pragma once
// Whether a standard stream is a terminal: a batch's progress line (rewritten in place with
// a carriage return) goes only where a person watches, never into a log or a pipe.

#include <cstdio>

namespace lb::platform {

// True when `stream` (stdout, stderr) is a terminal. The portable layer says so only where
// its system's C runtime can tell (Windows' _isatty); elsewhere false: no progress line.
bool isTerminal(std::FILE *stream);

} // namespace lb::platform
