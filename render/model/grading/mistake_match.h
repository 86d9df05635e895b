#pragma once
// Which known mistake of an exercise (exercise_mistakes.h) a failing submission's frames
// match, from the shares of pixels within the tolerance over its failing cases: the student
// against the reference, and against each mistake's frames. Only a clear match is said: a
// wrong hint costs a student more than none.

#include <vector>

namespace lb {

// A mistake matches when, over the failing cases, at least this mean share of the pixels is
// within the tolerance of its frames (the exercise's passShare is 0.99 per case; a student
// who makes the mistake in words of their own differs by a rounding here and there, and a
// wrong program that is not the mistake stays far below it: see bench/README.md's figures)...
constexpr double kMistakeMinShare = 0.97;
// ...and the pixels outside the tolerance are at most this part of those outside it against
// the reference: "far better than the reference", not merely as good.
constexpr double kMistakeOutsideRatio = 0.25;
// ...and where the mistake's frames differ from the reference's (what the mistake changes), at
// least this share of the student's pixels is the mistake's. Over the whole frame a student
// whose highlight is merely too small (a shininess of 100 where 10 is asked) looks much like
// one with no specular term at all, since most pixels have none; on the pixels the missing
// term changes, it does not. A mistake that draws as the reference does in those cases
// explains nothing and never matches.
constexpr double kMistakeSignatureShare = 0.97;
// The failing cases drawn with each mistake: the first ones, enough to tell, bounded so that
// 16 mistakes on 200 cases cost what 10 cases do.
constexpr int kMaxMistakeCases = 10;

struct MistakeShares
{
    double share = 0;          // the student's mean share within the tolerance of its frames
    double signatureShare = 0; // of the pixels it changes, those the student has as it does
    long signaturePixels = 0;  // how many it changes, over the cases
};

// The index in `mistakes` of the best mistake that matches, -1 when none does.
// `referenceShare`: the student's mean share against the reference over the same cases.
int bestMistake(double referenceShare, const std::vector<MistakeShares> &mistakes);

} // namespace lb
