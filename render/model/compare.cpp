#include "compare.h"

#include <algorithm>
#include <cmath>

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

} // namespace lb
