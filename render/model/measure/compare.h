#pragma once
// Compare views: two programs on one camera. Side A is the program on screen (the editor's),
// side B the built-in program with the compare settings' shading and specular model. This
// file says where each side is drawn; the renderer draws them, the probe reads them back.

#include "scene.h"

#include <QColor>
#include <QPoint>
#include <QRect>
#include <QSize>

#include <cstdint>

#include <glm/vec4.hpp>

namespace lb {

// |A - B| at or above this (out of 1) is white in the difference view's heat map.
constexpr float kDifferenceScale = 64.0f / 255.0f;

// The difference view's colour scale: a bar up the right edge of a frame of `frame` pixels
// (top-left origin), from 10% to 90% of its height, 16 pixels wide and 12 from the edge at UI
// scale 1, wider with `uiScale` so it is seen, and named, from the back row. The renderer draws
// it; the viewport writes its numbers beside it.
QRect differenceScaleBar(QSize frame, double uiScale);
// The same bar as GL's window coordinates (bottom-left origin): left, bottom, right, top.
glm::vec4 differenceScaleBarEdges(QSize frame, double uiScale);
// The differences (out of 255) the scale's ticks name, from 0 to the top (kDifferenceScale).
constexpr int kDifferenceTickStep = 16;

// The colour a view is cleared to where nothing is drawn (the renderer's), and as it reads
// back in 8 bits: grading and the tests tell drawn pixels from it.
constexpr float kBackgroundRgb[3] = {0.16f, 0.17f, 0.19f};
constexpr QRgb kBackgroundPixel = qRgb(41, 43, 48);

// The scene side B draws: the same scene with the compare settings' shading choices.
Scene sceneOfSide(const Scene &scene, bool sideB);

// The rectangle a side draws into (top-left origin): the left or right half side by side,
// the whole frame otherwise (the wipe shows each side on its part of it).
QRect viewRect(const Scene &scene, QSize frame, bool sideB);
// Side by side: the column where B starts; wipe: the wipe's column; -1 otherwise.
int dividerColumn(const Scene &scene, QSize frame);

// Which side a pixel of the frame shows, and where it lies in that side's own view.
struct PixelView
{
    bool sideB = false;
    QSize size;   // the side's view
    QPoint pixel; // in the side's view, top-left origin
};
PixelView viewOfPixel(const Scene &scene, QSize frame, QPoint pixel);

// The largest channel difference between the sides, as the difference view measures it, and
// the share of the pixels drawn (by either side: not the background on both) within a
// tolerance: the measure Check My Work and --grade give for a case (grading.h), so the view of
// a case and its line in the list count alike.
struct DifferenceStats
{
    bool valid = false;
    int largest = 0;          // out of 255
    QPoint at;                // where (top-left origin), the first such pixel
    double differing = 0.0;   // the fraction of all pixels that differ at all
    int tolerance = 2;        // per channel, out of 255
    qint64 drawn = 0;         // pixels either side drew
    double shareWithin = 1.0; // of those, within the tolerance (1 when none was drawn)
};

// Measures two frames of RGBA bytes, `size` large, rows bottom-up as glReadPixels gives them
// (`at` comes out top-left); alpha is not compared. A pixel within 1 of the background colour
// on both sides is not drawn (as grading counts it).
DifferenceStats measureDifference(const std::uint8_t *a, const std::uint8_t *b, QSize size,
                                  int tolerance = 2);

} // namespace lb
