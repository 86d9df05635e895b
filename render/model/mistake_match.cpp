#include "mistake_match.h"

namespace lb {

int bestMistake(double referenceShare, const std::vector<double> &mistakeShares)
{
    const double outsideReference = 1.0 - referenceShare;
    int best = -1;
    for (int i = 0; i < int(mistakeShares.size()); ++i) {
        const double share = mistakeShares[std::size_t(i)];
        const bool matches =
            share >= kMistakeMinShare && 1.0 - share <= kMistakeOutsideRatio * outsideReference;
        // The first of equals: the exercise's order says which the teacher thought likelier.
        if (matches && (best < 0 || share > mistakeShares[std::size_t(best)]))
            best = i;
    }
    return best;
}

} // namespace lb
