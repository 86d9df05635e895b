#pragma once
// The line a grading batch keeps up to date on a terminal while it runs (app/cli/grade.cpp shows
// it only where stderr is a terminal): how far it is, how long it took, how long is left.

#include <QString>

namespace lb {

// "graded 3/30, 0:12 elapsed, about 1:48 left": the estimate from the mean time of those
// done so far (none before the first is done); minutes:seconds, hours:minutes:seconds past
// an hour.
QString progressText(int done, int total, qint64 elapsedMs);

} // namespace lb
