#pragma once
// Loops that never end, named from the text before the driver sees it: Mesa drops such a loop
// without a word and draws garbage, a GPU driver resets the context. Named, as warnings on the
// loop's line:
//   for (;;), while (true), do ... while (true) with no break, return or discard in the body;
//   loops whose condition reads only names that nothing in the loop changes (no assignment,
//   ++ or -- in the body or the for's step) while the body calls no function of the file
//   (which could change a global or an out parameter).
// It reads conservatively: a loop it cannot be sure of is not named. Long loops that do end
// are the trial's business, not this.

#include "diagnostics.h"

#include <vector>

namespace lb {

std::vector<Diagnostic> endlessLoopWarnings(const QString &source, ShaderStage stage);

} // namespace lb
