#pragma once
// The command line's programs, one run each: a frame, a probe, a plot, a check, a benchmark,
// a saved scene, grading a class or one submission (--grade-one, Check My Work's child).
// main() calls this when the command line asks for no window (CommandLine::headless()).

#include "command_line.h"

namespace lb {

// Makes the application (a QApplication for a plot's chart, else a QGuiApplication) and
// runs what `cl` asks for; returns the process's exit code.
int runCommandLine(int &argc, char **argv, const CommandLine &cl);

} // namespace lb
