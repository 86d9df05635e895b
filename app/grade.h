#pragma once
// --grade: a class's submissions against an exercise (exercise.h), each in its own process
// (--grade-one) with a time limit, two at a time: a submission that does not compile, does
// not link, loops, hangs or crashes the driver is reported with its status and the batch goes
// on. Summary lines on standard output, a CSV report and one sheet per submission on request.

#include "command_line.h"

namespace lb {

// The batch. Exit code 0 when every submission was graded (whatever its grade), 2 when the
// exercise cannot be used or a submission could not be read (the others are still graded).
int runGrade(const CommandLine &commandLine);
// One submission, in the process the batch starts: its result as one line of JSON.
int runGradeOne(const CommandLine &commandLine);

} // namespace lb
