#include "mistake_match.h"

namespace lb {

int bestMistake(double referenceShare, const std::vector<MistakeShares> &mistakes)
{
    const double outsideReference = 1.0 - referenceShare;
    int best = -1;
    for (int i = 0; i < int(mistakes.size()); ++i) {
        const MistakeShares &m = mistakes[std::size_t(i)];
        // A student as far from the reference as nothing (cases where neither draws) is no
        // failure a mistake could explain.
        const bool matches = outsideReference > 0 && m.share >= kMistakeMinShare &&
                             1.0 - m.share <= kMistakeOutsideRatio * outsideReference &&
                             m.signaturePixels > 0 && m.signatureShare >= kMistakeSignatureShare;
        // The first of equals: the exercise's order says which the teacher thought likelier.
        if (matches && (best < 0 || m.share > mistakes[std::size_t(best)].share))
            best = i;
    }
    return best;
}

} // namespace lb
