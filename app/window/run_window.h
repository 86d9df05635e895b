#pragma once
// The window: the settings, the language, the main window with what the command line opens
// in it (a scene, a lesson, FILE..., shaders), --screenshot and --bench-edits. main() calls
// this when the command line asks for no headless run.

#include "command_line.h"

namespace lb {

// Makes the QApplication and runs the window until it closes (View > Language's restart
// included); returns the process's exit code.
int runWindow(int &argc, char **argv, const CommandLine &cl);

} // namespace lb
