#include "frame_look.h"

#include "compare.h"

#include <QCoreApplication>

#include <cstdlib>

namespace lb {

namespace {

// Within this of a colour per channel: the background as the driver stored it, black as a
// lit surface's darkest dithered or rounded value.
constexpr int kNear = 2;

bool near(const std::uint8_t *p, int r, int g, int b)
{
    return std::abs(p[0] - r) <= kNear && std::abs(p[1] - g) <= kNear &&
           std::abs(p[2] - b) <= kNear;
}

struct FrameLookMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::FrameLook)
};

} // namespace

FrameLook frameLook(const std::uint8_t *rgba, std::size_t count)
{
    const int br = qRed(kBackgroundPixel), bg = qGreen(kBackgroundPixel),
              bb = qBlue(kBackgroundPixel);
    bool anyObject = false;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t *p = rgba + 4 * i;
        if (near(p, br, bg, bb))
            continue;
        if (!near(p, 0, 0, 0))
            return FrameLook::Drawn;
        anyObject = true;
    }
    return anyObject ? FrameLook::AllBlack : FrameLook::AllBackground;
}

QString frameLookWarning(FrameLook look)
{
    switch (look) {
    case FrameLook::AllBackground:
        return FrameLookMessages::tr(
            "your program draws nothing: every pixel of the frame is the background (the "
            "object is outside the view, or a matrix fed nothing collapses it; the Bindings "
            "tab shows what feeds each input)");
    case FrameLook::AllBlack:
        return FrameLookMessages::tr(
            "your program draws the object all black: if it is not meant to be, a light or "
            "colour input it reads may be fed nothing (the Bindings tab shows what feeds each "
            "input)");
    case FrameLook::Drawn:
        break;
    }
    return {};
}

} // namespace lb
