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

// Why a program is refused for its frame's cost (`loops`: the program has loops).
QString slowFrameMessage(double estimatedMs, QSize target, double measuredMs, QSize measured,
                         double budgetMs, bool loops)
{
    const QString args[] = {durationText(estimatedMs),
                            QString::number(target.width()),
                            QString::number(target.height()),
                            durationText(measuredMs),
                            QString::number(measured.width()),
                            QString::number(measured.height()),
                            durationText(budgetMs)};
    //: %1 the estimate at %2x%3 pixels, %4 the time measured at %5x%6, %7 the budget
    return (loops ? ProgramTrialMessages::tr(
                        "drawing one frame with this program would take about %1 at %2x%3 "
                        "(measured %4 at %5x%6; the budget is %7): an endless or very long "
                        "loop?")
                  : ProgramTrialMessages::tr(
                        "drawing one frame with this program would take about %1 at %2x%3 "
                        "(measured %4 at %5x%6; the budget is %7): too much work for every "
                        "pixel?"))
        .arg(args[0], args[1], args[2], args[3], args[4], args[5], args[6]);
}
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
    const double small = quickest(sizes.small);
    const double large = quickest(sizes.large);
    const double targetPixels = pixelsOf(target);
    auto fit = [&](double pixels, double ms) {
        if (ms <= small) {
            // The bigger frame was not slower: a stall in the smaller one (another process
            // on the cores) hides what the pixels cost. Assumed all per pixel, the worst
            // case; an estimate over the budget is confirmed by a bigger frame below.
            r.perPixelMs = ms / pixels;
            r.fixedMs = 0.0;
        } else {
            r.perPixelMs = (ms - small) / (pixels - pixelsOf(sizes.small));
            r.fixedMs = std::max(0.0, small - r.perPixelMs * pixelsOf(sizes.small));
        }
        r.estimatedMs = r.fixedMs + r.perPixelMs * targetPixels;
    };
    fit(pixelsOf(sizes.large), large);
    if (r.estimatedMs <= budgetMs)
        return r;
    if (large < sizes.lightMs) {
        r.light = true;
        return r;
    }
    // Over the budget from two tiny frames: their difference is a few milliseconds, and a
    // stall in one is multiplied by thousands. A bigger frame confirms it, as big as about
    // 150 ms of per-pixel work by the estimate allows (and no bigger than the target).
    const double confirmPixels =
        std::min(targetPixels, std::max(2.0 * pixelsOf(sizes.large),
                                        std::min(budgetMs, 150.0) / std::max(r.perPixelMs, 1e-9)));
    const int side = std::max(1, int(std::lround(std::sqrt(confirmPixels))));
    const QSize confirm(side, side);
    // A second sample only where the first could be a light frame's stall.
    double confirmed = timeFrame(confirm);
    if (confirmed < 10.0 * sizes.lightMs)
        confirmed = std::min(confirmed, timeFrame(confirm));
    // The steeper of the slopes from the two small sizes: a stall in either flattens its own.
    r.perPixelMs = 0.0;
    for (const auto &[size, ms] : {std::pair{sizes.small, small}, std::pair{sizes.large, large}})
        if (pixelsOf(size) < pixelsOf(confirm)) // (a tiny view's confirming frame may be smaller)
            r.perPixelMs =
                std::max(r.perPixelMs, (confirmed - ms) / (pixelsOf(confirm) - pixelsOf(size)));
    if (r.perPixelMs <= 0.0)
        r.perPixelMs = confirmed / pixelsOf(confirm); // as above: all per pixel
    r.fixedMs = std::max(0.0, confirmed - r.perPixelMs * pixelsOf(confirm));
    r.estimatedMs = r.fixedMs + r.perPixelMs * targetPixels;
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
            refusalAt(vertex, fragment,
                      slowFrameMessage(r.estimatedMs, target, confirmed, confirm, budgetMs,
                                       !loopPlaces(vertex, ShaderStage::Vertex).empty() ||
                                           !loopPlaces(fragment, ShaderStage::Fragment).empty()));
    return r;
}

} // namespace lb
