#include "control_highlight.h"

#include <QPainter>
#include <QTimer>

namespace lb {

QPointer<ControlHighlight> ControlHighlight::s_current;

ControlHighlight::ControlHighlight(QWidget *window) : QWidget(window)
{
    setObjectName("controlHighlight");
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_DeleteOnClose);
    setFocusPolicy(Qt::NoFocus);
}

ControlHighlight *ControlHighlight::frame(const std::vector<QWidget *> &controls, int milliseconds)
{
    if (s_current)
        s_current->close();
    QWidget *window = nullptr;
    QRect area;
    for (QWidget *control : controls) {
        if (!control || !control->isVisible())
            continue;
        if (!window)
            window = control->window();
        if (control->window() != window) // a floating dock: the first window's controls
            continue;
        area |= QRect(control->mapTo(window, QPoint(0, 0)), control->size());
    }
    if (!window)
        return nullptr;
    auto *overlay = new ControlHighlight(window);
    const int margin = 4;
    overlay->setGeometry(area.adjusted(-margin, -margin, margin, margin));
    overlay->show();
    overlay->raise(); // over the docks and the view
    QTimer::singleShot(milliseconds, overlay, &QWidget::close);
    s_current = overlay;
    return overlay;
}

ControlHighlight *ControlHighlight::current()
{
    return s_current;
}

void ControlHighlight::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(255, 140, 0), 3)); // orange: visible on light and dark panels
    painter.drawRoundedRect(QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5), 4, 4);
}

} // namespace lb
