#include "probe_labels.h"

#include "compare.h"
#include "frames.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
// The names' font: the application's, bold, `pixelSize` high (paint and rectangles agree).
QFont labelFont(int pixelSize)
{
    QFont font;
    font.setBold(true);
    font.setPixelSize(std::max(pixelSize, 6));
    return font;
}
} // namespace

QRectF probeLabelRect(const PlacedLabel &label, int pixelSize)
{
    const QFontMetricsF metrics(labelFont(pixelSize));
    const double outline = std::max(2.0, pixelSize / 6.0); // the stroke paintProbeLabels draws
    const double w = metrics.horizontalAdvance(label.text) + 2.0 * outline;
    const double h = metrics.capHeight() + 2.0 * outline;
    return QRectF(label.position.x() - w / 2.0, label.position.y() - h / 2.0, w, h);
}

void separateLabels(std::vector<PlacedLabel> &labels, int pixelSize)
{
    constexpr int kRings = 6, kSpots = 12;
    const auto freeAt = [&](std::size_t i, QPointF at) {
        PlacedLabel moved = labels[i];
        moved.position = at;
        const QRectF r = probeLabelRect(moved, pixelSize);
        for (std::size_t j = 0; j < i; ++j)
            if (r.intersects(probeLabelRect(labels[j], pixelSize)))
                return false;
        return true;
    };
    for (std::size_t i = 1; i < labels.size(); ++i) {
        const QPointF home = labels[i].position;
        if (freeAt(i, home))
            continue;
        // Rings half a name apart, starting to the right and turning clockwise on screen.
        bool placed = false;
        for (int ring = 1; ring <= kRings && !placed; ++ring)
            for (int spot = 0; spot < kSpots && !placed; ++spot) {
                const double angle = 2.0 * M_PI * spot / kSpots;
                const double radius = 0.6 * pixelSize * ring;
                const QPointF at = home + radius * QPointF(std::cos(angle), std::sin(angle));
                if (freeAt(i, at)) {
                    labels[i].position = at;
                    placed = true;
                }
            }
    }
}

std::vector<PlacedLabel> placeLabels(const Scene &scene, QSize frame,
                                     const std::vector<ProbeLabel> &labels, int pixelSize,
                                     bool separate)
{
    std::vector<PlacedLabel> placed;
    for (const ProbeLabel &l : labels) {
        const QRect view = viewRect(scene, frame, l.sideB);
        if (view.isEmpty())
            continue;
        const Frames frames = computeFrames(scene, float(view.width()) / float(view.height()));
        const float w = float(view.width()), h = float(view.height());
        const glm::vec2 base = pixelOf(frames, l.eyeBase, w, h);
        const glm::vec2 tip = pixelOf(frames, l.eyeTip, w, h);
        const float size = float(pixelSize);
        const glm::vec2 along = tip - base;
        const glm::vec2 away = glm::length(along) > 0.5f * size ? glm::normalize(along)
                                                                : glm::normalize(glm::vec2(1, -1));
        const glm::vec2 p = tip + away * 0.75f * size;
        placed.push_back({QPointF(p.x, p.y) + QPointF(view.topLeft()), l.text, l.colour});
    }
    if (separate)
        separateLabels(placed, pixelSize);
    return placed;
}

void paintProbeLabels(QPainter &painter, const std::vector<PlacedLabel> &labels, int pixelSize)
{
    if (labels.empty())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const QFont font = labelFont(pixelSize);
    const QFontMetricsF metrics(font);
    for (const PlacedLabel &l : labels) {
        // The outline is a stroked path of the glyphs: crisp at any size, unlike text drawn
        // four times with an offset.
        const QPointF baseline = l.position + QPointF(-metrics.horizontalAdvance(l.text) / 2.0,
                                                      metrics.capHeight() / 2.0);
        QPainterPath path;
        path.addText(baseline, font, l.text);
        painter.setPen(QPen(QColor(0, 0, 0, 220), std::max(2.0, pixelSize / 6.0), Qt::SolidLine,
                            Qt::RoundCap, Qt::RoundJoin));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(path);
        painter.setPen(Qt::NoPen);
        painter.setBrush(l.colour);
        painter.drawPath(path);
    }
    painter.restore();
}

ProbeLabels::ProbeLabels(const SceneDocument *document, QWidget *viewport)
    : QWidget(viewport), m_document(document)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setGeometry(viewport->rect());
    viewport->installEventFilter(this);
    hide(); // shown while there are labels
}

void ProbeLabels::setLabels(std::vector<ProbeLabel> labels)
{
    m_labels = std::move(labels);
    setVisible(!m_labels.empty());
    update();
}

int ProbeLabels::pixelSize() const
{
    return int(std::lround(1.5 * QFontInfo(font()).pixelSize() * devicePixelRatioF()));
}

std::vector<PlacedLabel> ProbeLabels::placed(QSize frame, int pixelSize) const
{
    return placeLabels(m_document->scene(), frame, m_labels, pixelSize);
}

bool ProbeLabels::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == parent() && event->type() == QEvent::Resize)
        setGeometry(parentWidget()->rect());
    return false;
}

void ProbeLabels::paintEvent(QPaintEvent *)
{
    const qreal dpr = devicePixelRatioF();
    std::vector<PlacedLabel> labels = placed((QSizeF(size()) * dpr).toSize(), pixelSize());
    for (PlacedLabel &l : labels)
        l.position /= dpr; // frame pixels -> this widget's coordinates
    QPainter painter(this);
    paintProbeLabels(painter, labels, int(std::lround(pixelSize() / dpr)));
}

} // namespace lb
