#include "program_trial.h"

#include "loops.h"
#include "offscreen.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace lb {

namespace {
constexpr QSize kSmall(32, 32), kLarge(64, 64);
// Below this at 64x64 a program is light whatever the estimate says: tiny frames cost more per
// pixel than big ones (one tile, one thread on llvmpipe), so the estimate of a light program
// at 4K or 8K is several times too high and would refuse it for nothing. The built-in
// programs take about 1 ms; the freezing loop about 360 ms.
constexpr double kLightMs = 15.0;

QString seconds(double ms)
{
    return ms >= 1000.0 ? QString("%1 s").arg(ms / 1000.0, 0, 'f', ms >= 10000.0 ? 0 : 1)
                        : QString("%1 ms").arg(ms, 0, 'f', 0);
}
} // namespace

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

TrialResult tryProgram(OffscreenRenderer &offscreen, const Scene &scene, const QString &vertex,
                       const QString &fragment, QSize target, double budgetMs, int limitMs,
                       const std::function<void(const Diagnostic &)> &report)
{
    // A loop with no way out never finishes a frame: a GPU driver hangs on it, Mesa drops it
    // and draws garbage. No need to draw to know.
    for (const auto &[stage, text] :
         {std::pair{ShaderStage::Fragment, fragment}, std::pair{ShaderStage::Vertex, vertex}})
        for (Diagnostic d : certainEndlessLoops(text, stage)) {
            d.severity = Diagnostic::Severity::Error;
            d.message = "this program never finishes a frame: the loop here has no condition "
                        "(or an always-true one) and no break, return or discard";
            TrialResult r;
            r.refusal = d;
            return r;
        }

    // The watchdog: a driver stuck in a draw never returns to this thread.
    std::mutex mutex;
    std::condition_variable done;
    bool finished = false;
    std::thread watchdog([&] {
        std::unique_lock<std::mutex> lock(mutex);
        if (done.wait_for(lock, std::chrono::milliseconds(limitMs), [&] { return finished; }))
            return;
        report(refusalAt(vertex, fragment,
                         QString("drawing a %1x%2 frame with this program took more than %3: "
                                 "an endless or very long loop?")
                             .arg(kLarge.width())
                             .arg(kLarge.height())
                             .arg(seconds(limitMs))));
        std::_Exit(1);
    });
    // The quicker of two frames at each size: the machine's noise only ever adds time, and a
    // light program's per-pixel cost is small enough for that noise to count at 4K.
    const double small =
        std::min(offscreen.timeFrame(scene, kSmall), offscreen.timeFrame(scene, kSmall));
    const double large =
        std::min(offscreen.timeFrame(scene, kLarge), offscreen.timeFrame(scene, kLarge));
    {
        std::lock_guard<std::mutex> lock(mutex);
        finished = true;
    }
    done.notify_all();
    watchdog.join();

    // Two sizes separate what a frame costs anyway from what each pixel costs.
    TrialResult r;
    const double pixels[2] = {double(kSmall.width() * kSmall.height()),
                              double(kLarge.width() * kLarge.height())};
    r.perPixelMs = std::max(0.0, (large - small) / (pixels[1] - pixels[0]));
    r.fixedMs = std::max(0.0, small - r.perPixelMs * pixels[0]);
    r.estimatedMs = r.fixedMs + r.perPixelMs * double(target.width()) * double(target.height());
    if (r.estimatedMs > budgetMs && large >= kLightMs)
        r.refusal = refusalAt(
            vertex, fragment,
            QString("drawing one frame with this program would take about %1 at %2x%3 "
                    "(measured %4 at %5x%6; the budget is %7): an endless or very long loop?")
                .arg(seconds(r.estimatedMs))
                .arg(target.width())
                .arg(target.height())
                .arg(seconds(large))
                .arg(kLarge.width())
                .arg(kLarge.height())
                .arg(seconds(budgetMs)));
    return r;
}

} // namespace lb
