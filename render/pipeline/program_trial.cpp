#include "program_trial.h"

#include "loops.h"
#include "macro_expansion.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
// The translation context of this file's messages.
struct ProgramTrialMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::ProgramTrial)
};

} // namespace

QString durationText(double ms)
{
    //: a duration in seconds
    return ms >= 1000.0
               ? ProgramTrialMessages::tr("%1 s").arg(ms / 1000.0, 0, 'f', ms >= 10000.0 ? 0 : 1)
               //: a duration in milliseconds
               : ProgramTrialMessages::tr("%1 ms").arg(ms, 0, 'f', 0);
}

Diagnostic refusalAt(const QString &vertex, const QString &fragment, const QString &message)
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.stage = ShaderStage::Fragment;
    d.message = message;
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Fragment, fragment}, std::pair{ShaderStage::Vertex, vertex}}) {
        const std::vector<SourcePlace> loops = loopPlaces(text, stage);
        if (!loops.empty()) {
            d.stage = stage;
            d.line = loops.front().line;
            d.column = loops.front().column;
            break;
        }
    }
    return d;
}

QString slowFrameMessage(QSize target, double budgetMs, const QString &vertex,
                         const QString &fragment)
{
    const bool loops = !loopPlaces(vertex, ShaderStage::Vertex).empty() ||
                       !loopPlaces(fragment, ShaderStage::Fragment).empty();
    //: %1x%2 the frame's size in pixels, %3 the budget of one frame ("2.0 s")
    return (loops ? ProgramTrialMessages::tr("drawing one frame with this program at %1x%2 would "
                                             "take more than its budget of %3: an endless or "
                                             "very long loop?")
                  : ProgramTrialMessages::tr("drawing one frame with this program at %1x%2 would "
                                             "take more than its budget of %3: too much work for "
                                             "every pixel?"))
        .arg(QString::number(target.width()), QString::number(target.height()),
             durationText(budgetMs));
}

double TrialResult::estimateAt(double pixels) const
{
    const double linear = fixedMs + perPixelMs * pixels;
    return referenceMs > 0.0 ? std::min(linear, referenceMs + extraPerPixelMs * pixels) : linear;
}

std::optional<Diagnostic> refusalWithoutFrames(const QString &vertex, const QString &fragment)
{
    // Macros that grow past the expansion's bound would grow the driver's preprocessor
    // without one (issue 29): refused before anything else reads them.
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Vertex, vertex}, std::pair{ShaderStage::Fragment, fragment}})
        if (std::optional<Diagnostic> refusal = readLoops(text, stage).expansionRefusal)
            return refusal;
    // A loop with no way out never finishes a frame: a GPU driver hangs on it, Mesa drops it
    // and draws garbage. No need to draw to know.
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Fragment, fragment}, std::pair{ShaderStage::Vertex, vertex}})
        if (const auto refusals = certainEndlessLoops(text, stage, true); !refusals.empty())
            return refusals.front(); // the first loop's
    return std::nullopt;
}

TrialResult tryProgram(const QString &vertex, const QString &fragment, QSize target,
                       double budgetMs, const TrialSizes &sizes,
                       const std::function<double(QSize)> &timeFrame,
                       const std::function<double(QSize)> &timeReference)
{
    TrialResult r;
    r.refusal = refusalWithoutFrames(vertex, fragment);
    if (r.refusal)
        return r;

    // A tiny frame first: the driver generates the program's code at its first draw
    // (llvmpipe: ~100 ms), which is no frame's cost. Then the quicker of two frames at each
    // size: noise only ever adds time.
    timeFrame(QSize(4, 4));
    // (A first frame already heavy is not drawn again: the confirming frame below catches a
    // stall that made it look heavy.)
    auto quickest = [&](QSize size) {
        const double first = timeFrame(size);
        return first > sizes.lightMs ? first : std::min(first, timeFrame(size));
    };
    auto pixelsOf = [](QSize size) { return double(size.width()) * double(size.height()); };
    // Each frame as many pixels as its size says, in the target's shape: the camera's aspect
    // decides how much of a frame the object covers (a square frame of a 4:3 target holds
    // a third more of the object, each pixel cost a third more).
    const double aspect = double(target.width()) / double(std::max(1, target.height()));
    auto shaped = [&](double pixels) {
        return QSize(std::max(1, int(std::lround(std::sqrt(pixels * aspect)))),
                     std::max(1, int(std::lround(std::sqrt(pixels / aspect)))));
    };
    const QSize smallSize = shaped(pixelsOf(sizes.small)),
                largeSize = shaped(pixelsOf(sizes.large));
    const double small = quickest(smallSize);
    double large = quickest(largeSize);
    const double targetPixels = pixelsOf(target);
    auto fit = [&](double pixels, double ms) {
        if (ms <= small) {
            // The bigger frame was not slower: a stall in the smaller one (another process
            // on the cores) hides what the pixels cost. Assumed all per pixel, the worst
            // case; an estimate over the budget is confirmed by a bigger frame below.
            r.perPixelMs = ms / pixels;
            r.fixedMs = 0.0;
        } else {
            r.perPixelMs = (ms - small) / (pixels - pixelsOf(smallSize));
            r.fixedMs = std::max(0.0, small - r.perPixelMs * pixelsOf(smallSize));
        }
        r.estimatedMs = r.fixedMs + r.perPixelMs * targetPixels;
    };
    fit(pixelsOf(largeSize), large);
    if (r.estimatedMs <= budgetMs)
        return r;
    if (large < sizes.lightMs) {
        r.light = true;
        return r;
    }
    // Far over the budget (a loop that runs until the driver cuts it short): the large frame
    // measured a second time says so again, and no bigger frame is drawn for it (a runaway's
    // would take most of a second). Small frames overestimate what each pixel costs (partly
    // covered blocks are shaded whole), but by 2.5 times at most on the example exercise (the
    // 5000-step loop: 3.1 s estimated, 1.24 s at 320x240), short of this.
    if (r.estimatedMs > kFarOverBudget * budgetMs) {
        large = std::min(large, timeFrame(largeSize));
        fit(pixelsOf(largeSize), large);
        if (r.estimatedMs > kFarOverBudget * budgetMs) {
            r.refusal =
                refusalAt(vertex, fragment, slowFrameMessage(target, budgetMs, vertex, fragment));
            return r;
        }
    }
    // Over the budget from two tiny frames. Their difference is a few milliseconds (a stall in
    // one would be multiplied by thousands on the wall clock), and tiny frames shade more
    // pixels than they cover (llvmpipe shades 4x4 blocks whole: the heavy 5000-step loop of
    // issue 47 costs 31 us a pixel at 62x62 and 17 at 320x240). Bigger frames confirm it, each
    // with 4 times the pixels of the one before, and what a pixel costs is the difference
    // between the last two: drawn while the estimate stays over the budget, the target is not
    // reached and the next frame would cost less than the cap (half the budget, at most 1 s).
    const double capMs = std::clamp(budgetMs / 2.0, 150.0, 1000.0);
    QSize before = largeSize, confirm = largeSize;
    double beforeMs = large, confirmed = large;
    do {
        confirm = shaped(std::min(targetPixels, 4.0 * pixelsOf(before)));
        if (pixelsOf(confirm) <= pixelsOf(before)) // (a tiny view: the large frame was its size)
            break;
        // A second sample only where the first could be a light frame's stall.
        confirmed = timeFrame(confirm);
        if (confirmed < 10.0 * sizes.lightMs)
            confirmed = std::min(confirmed, timeFrame(confirm));
        r.perPixelMs = (confirmed - beforeMs) / (pixelsOf(confirm) - pixelsOf(before));
        if (r.perPixelMs <= 0.0) // a stall in the frame before: all per pixel, the worst case
            r.perPixelMs = confirmed / pixelsOf(confirm);
        r.fixedMs = std::max(0.0, confirmed - r.perPixelMs * pixelsOf(confirm));
        r.estimatedMs = r.fixedMs + r.perPixelMs * targetPixels;
        before = confirm;
        beforeMs = confirmed;
    } while (r.estimatedMs > budgetMs && pixelsOf(confirm) < targetPixels &&
             4.0 * confirmed < capMs);
    if (timeReference && r.estimatedMs > budgetMs) {
        // What the built-in program takes on the same frame is the scene's cost: only the
        // rest grows with the pixels this program shades.
        r.referenceMs = std::min(timeReference(confirm), timeReference(confirm));
        r.extraPerPixelMs = std::max(0.0, confirmed - r.referenceMs) / pixelsOf(confirm);
        r.estimatedMs = r.estimateAt(targetPixels);
        // Not even twice the built-in program's frame: the difference is the machine's noise,
        // which the pixels of a big target would multiply into seconds.
        if (confirmed < 2.0 * r.referenceMs) {
            r.nearReference = true;
            return r;
        }
    }
    if (r.estimatedMs > budgetMs)
        r.refusal =
            refusalAt(vertex, fragment, slowFrameMessage(target, budgetMs, vertex, fragment));
    return r;
}

} // namespace lb
