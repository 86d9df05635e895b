#pragma once
// --grade: a class's submissions against an exercise (exercise.h), each in its own process
// (--grade-one) with a time limit, two at a time: a submission that does not compile, does
// not link, loops, hangs or crashes the driver is reported with its status and the batch goes
// on. Summary lines on standard output as submissions finish (in the order given), a CSV
// report written again after each one, and one sheet per submission on request: a batch
// stopped by SIGINT, SIGTERM or SIGHUP keeps what it finished, stops its children and exits
// with 130, 143 or 129.

#include "command_line.h"

namespace lb {

// The batch. Exit code 0 when every submission was graded (whatever its grade), 2 when the
// exercise cannot be used, the report or a sheet has no place that can take it (said before
// any is graded) or a submission could not be read (the others are still graded), 1 when the
// report, a sheet or the sheet folder's list could not be written (a full disk: the old report
// is left as it was).
// Exit code 3 with --report-format github when the submission did not pass every case.
int runGrade(const CommandLine &commandLine);
// First of all for --grade --report-format coderunner: standard error goes to the null device
// (CodeRunner takes any word there for the grader's failure), Qt's warnings included.
void quietStandardErrorForGrade(const CommandLine &commandLine);
// A batch that cannot grade anyone (no display, a faulty exercise): `error` on stderr and in
// the report where its format can say it (the platforms' files). Returns `exitCode`.
int failGrade(const CommandLine &commandLine, const QString &error, int exitCode = 2);
// One submission, in the process the batch starts: its result as one line of JSON.
int runGradeOne(const CommandLine &commandLine);
// The frames the batch hands its children, drawn once (grade_frames.h).
int runGradePrepare(const CommandLine &commandLine);

} // namespace lb
