#pragma once
// Loops that never end, named from the text before the driver sees it: Mesa drops such a loop
// without a word and draws garbage, a GPU driver resets the context. Named, as warnings on the
// loop's line:
//   for (;;), while (true), do ... while (true) with no break, return or discard in the body;
//   for (int i = 0; i < 1000000000; i++): a counted loop of ten million steps or more (as
//   good as endless for a frame; llvmpipe cuts it short, a GPU driver resets the context);
//   loops whose condition reads only names that nothing in the loop changes (no assignment,
//   ++ or -- in the body or the for's step) while the body calls no function of the file
//   (which could change a global or an out parameter).
//   for (int i = 0; i >= 0; i++): a counter moving away from its bound, which only wrapping
//   around ends (2^31 steps), in the vertex stage as in the fragment stage.
// It reads the code after the source's macros are expanded (macro_expansion.h): a loop a macro
// writes is named on the line where the macro is used, with the macro's name. It reads
// conservatively: a loop it cannot be sure of is not named. Long loops that do end are the
// trial's business, not this.

#include "diagnostics.h"

#include <optional>
#include <vector>

namespace lb {

// Where a loop starts (for, while, do).
struct SourcePlace
{
    int line = 0; // 1-based
    int column = 0;
};

// What the loop reader finds in one stage's text, all from one macro expansion of it: the
// build's warnings, the trial's refusals and places and the window's short-loop test below
// are each answered from this. The last few readings are kept (per thread), so a program's
// text is read once on its way however many of them ask.
struct LoopReading
{
    struct Endless
    {
        Diagnostic warning;
        QString refusal; // the program's, for a loop certain never to end (no condition,
                         // always true, or as good as endless); empty for the others
    };
    std::vector<Endless> endless;
    std::vector<SourcePlace> places; // every loop, in order
    // Every loop a counted `for` (no while, no do), the longest of this many steps.
    bool onlyCounted = true;
    double longestCounted = 0.0;
    // The macros grew past the expansion's bound (macro_expansion.h): the text is refused
    // before anything reads it, and nothing above is read (no loops, not only counted ones).
    std::optional<Diagnostic> expansionRefusal;
};
LoopReading readLoops(const QString &source, ShaderStage stage = ShaderStage::Fragment);

std::vector<Diagnostic> endlessLoopWarnings(const QString &source, ShaderStage stage);
// Only the loops that are certain never to end once reached: no condition or an always-true
// one, and no way out (not those whose condition might be false the first time). As warnings
// on their lines, or `asRefusals`: as errors that say why the whole program is refused ("this
// program never finishes a frame: the loop here ...").
std::vector<Diagnostic> certainEndlessLoops(const QString &source, ShaderStage stage,
                                            bool asRefusals = false);

// Where the source's loops start (for, while, do), in order: where a program that draws too
// slowly most likely spends its time.
std::vector<SourcePlace> loopPlaces(const QString &source,
                                    ShaderStage stage = ShaderStage::Fragment);

// Whether every loop of the source is a counted one of at most `maxSteps` steps (a literal or
// a #define'd bound: `for (int i = 0; i < MAX_LIGHTS; ++i)`); true without loops.
// (A source whose macros pass the expansion's bound is read as far as the bound.)
bool onlyShortLoops(const QString &source, int maxSteps, ShaderStage stage = ShaderStage::Fragment);

} // namespace lb
