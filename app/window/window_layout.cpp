#include "window_layout.h"

#include <QApplication>
#include <QFont>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
constexpr int kWideFrom = 1600;

struct UiScale
{
    QFont base; // the font Qt started with
    double scale = 1.0;
};
UiScale &uiScale()
{
    static UiScale s{QApplication::font(), 1.0};
    return s;
}
} // namespace

DockLayout dockLayoutFor(int availableWidth)
{
    return availableWidth >= kWideFrom ? DockLayout::Wide : DockLayout::Compact;
}

QRect initialGeometry(const QRect &available, QSize preferred)
{
    QRect r(QPoint(0, 0), preferred.boundedTo(available.size()));
    r.moveCenter(available.center());
    return r;
}

DockWidths dockWidths(DockLayout layout, int windowWidth)
{
    const double w = windowWidth;
    switch (layout) {
    case DockLayout::Wide:
        return {int(std::lround(std::clamp(w * 0.22, 300.0, 420.0))), int(std::lround(w * 0.32))};
    case DockLayout::Compact:
        return {int(std::lround(std::clamp(w * 0.25, 240.0, 360.0))), int(std::lround(w * 0.29))};
    case DockLayout::Presentation: // the panels share the editor's column; the view keeps 60%
        return {int(std::lround(w * 0.38)), int(std::lround(w * 0.38))}; // 2% for the handle
    }
    return {300, 400};
}

double clampUiScale(double scale)
{
    return std::isfinite(scale) ? std::clamp(scale, kMinUiScale, kMaxUiScale) : 1.0;
}

void applyUiScale(double scale)
{
    UiScale &s = uiScale();
    s.scale = clampUiScale(scale);
    QFont font = s.base;
    if (s.base.pointSizeF() > 0)
        font.setPointSizeF(s.base.pointSizeF() * s.scale);
    else
        font.setPixelSize(int(std::lround(s.base.pixelSize() * s.scale)));
    QApplication::setFont(font);
}

double currentUiScale()
{
    return uiScale().scale;
}

} // namespace lb
