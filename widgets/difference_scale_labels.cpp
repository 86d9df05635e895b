#include "difference_scale_labels.h"

#include "compare.h"

#include <QEvent>
#include <QFontInfo>
#include <QFontMetrics>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lb {

DifferenceScaleLabels::DifferenceScaleLabels(QWidget *viewport) : QWidget(viewport)
{
    setObjectName("differenceScaleLabels");
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setGeometry(viewport->rect());
    viewport->installEventFilter(this);
    hide();
}

void DifferenceScaleLabels::setUiScale(double scale)
{
    m_uiScale = scale;
    update();
}

void DifferenceScaleLabels::setShown(bool shown)
{
    if (shown != isVisible())
        setVisible(shown);
}

int DifferenceScaleLabels::pixelSize() const
{
    return QFontInfo(font()).pixelSize();
}

std::vector<DifferenceScaleLabels::Tick> DifferenceScaleLabels::ticks() const
{
    // The bar in the frame's device pixels, as the renderer draws it, back in this widget's.
    const qreal dpr = devicePixelRatioF();
    const QRect frameBar = differenceScaleBar((QSizeF(size()) * dpr).toSize(), m_uiScale);
    const QRectF bar(QPointF(frameBar.topLeft()) / dpr, QSizeF(frameBar.size()) / dpr);
    const QFontMetrics metrics(font());
    const int top = int(std::lround(kDifferenceScale * 255.0f));
    const int pad = std::max(2, metrics.height() / 8);
    std::vector<Tick> ticks;
    for (int value = 0; value <= top; value += kDifferenceTickStep) {
        // Above the top the scale stays white: the top tick says "and more".
        //: the top of the difference scale: this difference (of 255) and more
        const QString text = value == top ? tr("%1+").arg(value) : QString::number(value);
        const double y = bar.bottom() - bar.height() * double(value) / double(top);
        const int w = metrics.horizontalAdvance(text) + 2 * pad;
        const int h = metrics.height();
        const int right = int(std::floor(bar.left())) - pad;
        ticks.push_back({QRect(right - w, int(std::lround(y - h / 2.0)), w, h), text});
    }
    //: the difference scale's title: |A-B| the difference of sides A and B, out of 255
    const QString title = tr("|A-B| of 255");
    const int w = metrics.horizontalAdvance(title) + 2 * pad;
    // Above the top tick, which is centred on the bar's top.
    const int h = metrics.height();
    ticks.push_back({QRect(int(std::lround(bar.right())) - w,
                           int(std::floor(bar.top())) - h / 2 - pad - h, w, h),
                     title});
    return ticks;
}

int DifferenceScaleLabels::leftOfTicks() const
{
    int left = width();
    for (const Tick &t : ticks())
        left = std::min(left, t.box.left());
    return std::max(left, 1);
}

bool DifferenceScaleLabels::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == parent() && event->type() == QEvent::Resize)
        setGeometry(parentWidget()->rect());
    return false;
}

void DifferenceScaleLabels::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    for (const Tick &t : ticks()) {
        // A dark backing: white numbers stay legible over the heat map's white and yellow.
        painter.fillRect(t.box, QColor(0, 0, 0, 190));
        painter.setPen(Qt::white);
        painter.drawText(t.box, Qt::AlignCenter, t.text);
    }
}

} // namespace lb
