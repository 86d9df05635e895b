#pragma once
// A user's program tried before the command line draws with it: small frames with a time
// limit, the frame time at the asked size estimated from them. A program over the budget is
// refused with a diagnostic on its first loop's line (where such time is spent); a driver that
// does not come back within the limit ends the process with that diagnostic, exit code 1.

#include "diagnostics.h"

#include <QSize>

#include <functional>
#include <optional>

namespace lb {

class OffscreenRenderer;
struct Scene;

struct TrialResult
{
    double fixedMs = 0.0;              // a frame's cost whatever its size
    double perPixelMs = 0.0;           // and for each pixel
    double estimatedMs = 0.0;          // one frame at the asked size
    std::optional<Diagnostic> refusal; // set when the program is refused
};

// `report` prints the refusal of a program that hangs, just before the process ends.
TrialResult tryProgram(OffscreenRenderer &offscreen, const Scene &scene, const QString &vertex,
                       const QString &fragment, QSize target, double budgetMs, int limitMs,
                       const std::function<void(const Diagnostic &)> &report);

// Where a refusal points: the fragment shader's first loop, else the vertex shader's, else
// the fragment shader with no line.
Diagnostic refusalAt(const QString &vertex, const QString &fragment, const QString &message);

} // namespace lb
