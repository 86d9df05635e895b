#include "compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace lb {

Scene sceneOfSide(const Scene &scene, bool sideB)
{
    Scene s = scene;
    if (sideB) {
        s.shading.shading = scene.compare.shading;
        s.shading.specular = scene.compare.specular;
    }
    return s;
}

QRect differenceScaleBar(QSize frame, double uiScale)
{
    const int width = int(std::lround(16.0 * uiScale)), margin = int(std::lround(12.0 * uiScale));
    const int top = int(std::lround(0.1 * frame.height()));
    const int bottom = int(std::lround(0.9 * frame.height()));
    return QRect(frame.width() - margin - width, top, width, std::max(bottom - top, 1));
}

glm::vec4 differenceScaleBarEdges(QSize frame, double uiScale)
{
    const QRect bar = differenceScaleBar(frame, uiScale);
    return glm::vec4(bar.left(), frame.height() - bar.bottom() - 1, bar.right() + 1,
                     frame.height() - bar.top());
}

QRect viewRect(const Scene &scene, QSize frame, bool sideB)
{
    if (scene.compare.mode != CompareMode::SideBySide)
        return QRect(QPoint(0, 0), frame);
    const int half = frame.width() / 2;
    return sideB ? QRect(half, 0, frame.width() - half, frame.height())
                 : QRect(0, 0, half, frame.height());
}

int dividerColumn(const Scene &scene, QSize frame)
{
    switch (scene.compare.mode) {
    case CompareMode::SideBySide:
        return frame.width() / 2;
    case CompareMode::Wipe:
        return int(std::lround(std::clamp(scene.compare.wipe, 0.0f, 1.0f) * frame.width()));
    default:
        return -1;
    }
}

PixelView viewOfPixel(const Scene &scene, QSize frame, QPoint pixel)
{
    PixelView v;
    const int divider = dividerColumn(scene, frame);
    v.sideB = divider >= 0 && pixel.x() >= divider;
    const QRect rect = viewRect(scene, frame, v.sideB);
    v.size = rect.size();
    v.pixel = pixel - rect.topLeft();
    return v;
}

DifferenceStats measureDifference(const std::uint8_t *a, const std::uint8_t *b, QSize size,
                                  int tolerance)
{
    const std::size_t n =
        std::size_t(std::max(size.width(), 0)) * std::size_t(std::max(size.height(), 0)) * 4;
    DifferenceStats stats;
    stats.valid = true;
    stats.tolerance = tolerance;
    if (n == 0)
        return stats;
    const int background[3] = {qRed(kBackgroundPixel), qGreen(kBackgroundPixel),
                               qBlue(kBackgroundPixel)};
    const auto isBackground = [&](const std::uint8_t *p) {
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(p[c]) - background[c]) > 1)
                return false;
        return true;
    };
    std::size_t differing = 0, within = 0;
    for (std::size_t i = 0; i < n; i += 4) {
        int d = 0;
        for (std::size_t c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(a[i + c]) - int(b[i + c])));
        differing += d > 0 ? 1 : 0;
        if (!isBackground(a + i) || !isBackground(b + i)) {
            ++stats.drawn;
            within += d <= tolerance ? 1 : 0;
        }
        if (d > stats.largest) {
            stats.largest = d;
            const int p = int(i / 4);
            stats.at = QPoint(p % size.width(), size.height() - 1 - p / size.width());
        }
    }
    stats.differing = double(differing) / double(n / 4);
    stats.shareWithin = stats.drawn ? double(within) / double(stats.drawn) : 1.0;
    return stats;
}

} // namespace lb
