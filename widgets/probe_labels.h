#pragma once
// The names of the probe's arrows (N, V, L, H, R) over the view. QPainter text drawn inside
// paintGL comes out garbled on Mesa, so the names are painted by the raster engine: on screen
// by a transparent child widget over the viewport, in an exported image onto the QImage, by
// one function for both. Their size follows the UI scale (the widget's font).

#include "scene_document.h"

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <glm/vec3.hpp>

#include <vector>

class QPainter;

namespace lb {

// A name at an arrow's tip: the arrow's start and tip in eye coordinates, on side A or B of
// a compare view.
struct ProbeLabel
{
    glm::vec3 eyeBase;
    glm::vec3 eyeTip;
    bool sideB = false;
    QString text;
    QColor colour;
};

// A name placed in a frame: pixels from its top-left corner.
struct PlacedLabel
{
    QPointF position;
    QString text;
    QColor colour;
};

// Where the labels land in a frame of `frame` pixels showing `scene`: past the arrow's tip on
// screen, by about half the names' height `pixelSize`, so a name never hides its arrow or the
// point (V, pointing at the eye, is a dot: its name goes up and right of it).
// `separate`: a name that would overlap one placed before it moves to the nearest free spot
// around its place (separateLabels); false only to see where they would overlap.
std::vector<PlacedLabel> placeLabels(const Scene &scene, QSize frame,
                                     const std::vector<ProbeLabel> &labels, int pixelSize,
                                     bool separate = true);
// The rectangle a name covers when painted `pixelSize` high at its position, outline included.
QRectF probeLabelRect(const PlacedLabel &label, int pixelSize);
// Moves names off each other's rectangles (L under H, V under H when the light is near the
// eye): each in turn, if it overlaps one before it, goes to the first free spot on rings
// around its place. Bounded: a few rings of twelve spots each, whatever the input.
void separateLabels(std::vector<PlacedLabel> &labels, int pixelSize);
// Paints the names centred on their positions (the painter's coordinates), bold, `pixelSize`
// pixels high, in their colour with a dark outline that keeps them readable on any surface.
void paintProbeLabels(QPainter &painter, const std::vector<PlacedLabel> &labels, int pixelSize);

class ProbeLabels : public QWidget
{
    Q_OBJECT
public:
    // Covers `viewport` (which draws `document`'s scene) and follows its size.
    ProbeLabels(const SceneDocument *document, QWidget *viewport);

    void setLabels(std::vector<ProbeLabel> labels);
    const std::vector<ProbeLabel> &labels() const { return m_labels; }
    // The names' height in device pixels on screen (1.5 times the UI's font).
    int pixelSize() const;
    // The names as placed over a frame of `frame` pixels, `pixelSize` high.
    std::vector<PlacedLabel> placed(QSize frame, int pixelSize) const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override; // the viewport's resizes
    void paintEvent(QPaintEvent *event) override;

private:
    const SceneDocument *m_document;
    std::vector<ProbeLabel> m_labels;
};

} // namespace lb
