#pragma once
// A user's program tried before it is used: a loop with no way out refuses it at once; every
// other program is timed, loops or not (25,000 lines of sin() without one took 4 minutes a
// frame): two small frames separate what a frame costs anyway from what
// each pixel costs, and the frame at the size it will be drawn is estimated; far over the
// budget, the larger small frame drawn again confirms it; over it, a bigger frame confirms it
// (a stall in a tiny frame would be multiplied by thousands) and it is refused with a
// diagnostic on its first loop's line, which names the budget, never a measured figure. The frames
// are drawn and timed by the caller (the window's context, or the command line's; processor time on
// a software rasterizer, Renderer::renderTimed, so that a busy machine does not change the
// verdict), so this holds no GL.

#include "diagnostics.h"

#include <QSize>

#include <functional>
#include <optional>

namespace lb {

struct TrialSizes
{
    QSize small, large;
    // Below this for the large frame no confirmation is drawn: the program is light.
    double lightMs;
};
// The command line's (64x64: the built-in programs take ~1 ms there, the freezing
// loop ~360 ms) and the window's, smaller so that a slow program blocks it briefly.
constexpr TrialSizes kCommandLineTrial{QSize(32, 32), QSize(64, 64), 2.0};
constexpr TrialSizes kWindowTrial{QSize(16, 16), QSize(32, 32), 1.0};
// Grading's: a submission's frame is small (320x240), and a class may hold many runaways,
// each of which pays for the frames that measure it (at 32x32, 0.2 s on llvmpipe).
constexpr TrialSizes kGradingTrial = kWindowTrial;
// An estimate this many times the budget is refused without a bigger frame.
constexpr double kFarOverBudget = 4.0;

struct TrialResult
{
    double fixedMs = 0.0;     // a frame's cost whatever its size
    double perPixelMs = 0.0;  // and for each pixel
    double estimatedMs = 0.0; // one frame at the asked size
    // Where a bigger frame was measured against the built-in program: the scene's own cost
    // and what the program adds per pixel on top (0 when not measured).
    double referenceMs = 0.0, extraPerPixelMs = 0.0;
    // Accepted whatever the estimate: its small frames were too light to tell anything, or
    // a bigger one took less than twice the built-in program's.
    bool light = false, nearReference = false;
    std::optional<Diagnostic> refusal; // set when the program is refused
    // The estimate for a frame of `pixels` (the view grown, an export): as estimatedMs was.
    double estimateAt(double pixels) const;
    // Whether the accepted program would be refused at a frame of `pixels`.
    bool overBudgetAt(double pixels, double budgetMs) const
    {
        return !light && !nearReference && estimateAt(pixels) > budgetMs;
    }
};

// A refusal before any frame when a loop has no way out (no frame needs drawing to know).
std::optional<Diagnostic> refusalWithoutFrames(const QString &vertex, const QString &fragment);

// `timeFrame(size)`: the milliseconds one frame with the program takes at `size`, waited for.
// `timeReference(size)`, when given, the same with the built-in program: what the scene costs
// anyway (a big mesh's vertices, the rasterizer's bins, which do not grow with the pixels as
// the estimate assumes). Then only the program's own extra cost is held to the budget.
TrialResult tryProgram(const QString &vertex, const QString &fragment, QSize target,
                       double budgetMs, const TrialSizes &sizes,
                       const std::function<double(QSize)> &timeFrame,
                       const std::function<double(QSize)> &timeReference = {});

// Why a program is refused for its frame's cost at `target`: over the budget, which it names,
// never by how much. An estimate has the machine's noise in it (a runaway's was 5 to 10 times
// the budget from one run to the next): a report graded twice, on a quiet machine or a busy
// one, says the same words. The loop's question where the program has one.
QString slowFrameMessage(QSize target, double budgetMs, const QString &vertex,
                         const QString &fragment);
// Where a refusal points: the fragment shader's first loop, else the vertex shader's, else
// the fragment shader with no line.
Diagnostic refusalAt(const QString &vertex, const QString &fragment, const QString &message);
// "120 ms", "3.4 s", "40 s"
QString durationText(double ms);

} // namespace lb
