#include "program_trial.h"

#include "loops.h"

#include <algorithm>

namespace lb {

QString durationText(double ms)
{
    return ms >= 1000.0 ? QString("%1 s").arg(ms / 1000.0, 0, 'f', ms >= 10000.0 ? 0 : 1)
                        : QString("%1 ms").arg(ms, 0, 'f', 0);
}

Diagnostic refusalAt(const QString &vertex, const QString &fragment, const QString &message)
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.stage = ShaderStage::Fragment;
    d.message = message;
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Fragment, fragment}, std::pair{ShaderStage::Vertex, vertex}}) {
        const std::vector<SourcePlace> loops = loopPlaces(text);
        if (!loops.empty()) {
            d.stage = stage;
            d.line = loops.front().line;
            d.column = loops.front().column;
            break;
        }
    }
    return d;
}

TrialResult tryProgram(const QString &vertex, const QString &fragment, QSize target,
                       double budgetMs, const TrialSizes &sizes,
                       const std::function<double(QSize)> &timeFrame)
{
    TrialResult r;
    // A loop with no way out never finishes a frame: a GPU driver hangs on it, Mesa drops it
    // and draws garbage. No need to draw to know.
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Fragment, fragment}, std::pair{ShaderStage::Vertex, vertex}})
        for (Diagnostic d : certainEndlessLoops(text, stage)) {
            d.severity = Diagnostic::Severity::Error;
            d.message = "this program never finishes a frame: the loop here has no condition "
                        "(or an always-true one) and no break, return or discard";
            r.refusal = d;
            return r;
        }

    // A tiny frame first: the driver generates the program's code at its first draw
    // (llvmpipe: ~100 ms), which is no frame's cost.
    timeFrame(QSize(4, 4));
    // The quicker of two frames at each size (noise only ever adds time), the second one
    // skipped when the first is already heavy.
    auto quickest = [&](QSize size) {
        const double first = timeFrame(size);
        return first > sizes.lightMs ? first : std::min(first, timeFrame(size));
    };
    const double small = quickest(sizes.small);
    const double large = quickest(sizes.large);
    const double pixels[2] = {double(sizes.small.width() * sizes.small.height()),
                              double(sizes.large.width() * sizes.large.height())};
    r.perPixelMs = std::max(0.0, (large - small) / (pixels[1] - pixels[0]));
    r.fixedMs = std::max(0.0, small - r.perPixelMs * pixels[0]);
    r.estimatedMs = r.fixedMs + r.perPixelMs * double(target.width()) * double(target.height());
    if (r.estimatedMs > budgetMs && large >= sizes.lightMs)
        r.refusal = refusalAt(
            vertex, fragment,
            QString("drawing one frame with this program would take about %1 at %2x%3 "
                    "(measured %4 at %5x%6; the budget is %7): an endless or very long loop?")
                .arg(durationText(r.estimatedMs))
                .arg(target.width())
                .arg(target.height())
                .arg(durationText(large))
                .arg(sizes.large.width())
                .arg(sizes.large.height())
                .arg(durationText(budgetMs)));
    return r;
}

} // namespace lb
