#include "screen_blank.h"

#include <QApplication>
#include <QEvent>
#include <QPainter>

namespace lb {

ScreenBlank::ScreenBlank(QWidget *window) : QWidget(window)
{
    setObjectName("screenBlank");
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::BlankCursor); // no arrow left on the black screen
    window->installEventFilter(this);
    hide();
}

void ScreenBlank::blank()
{
    if (isBlank())
        return;
    setGeometry(parentWidget()->rect());
    show();
    raise();
    setFocus();
    // Every key, wherever it is sent, comes here first: the window's shortcuts (the stepping
    // keys, C, G ...) must not act under the black screen.
    qApp->installEventFilter(this);
    emit blankChanged(true);
}

void ScreenBlank::unblank()
{
    if (!isBlank())
        return;
    qApp->removeEventFilter(this);
    hide();
    emit blankChanged(false);
}

bool ScreenBlank::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == parent() && event->type() == QEvent::Resize && isBlank())
        setGeometry(parentWidget()->rect());
    if (!isBlank())
        return false;
    switch (event->type()) {
    case QEvent::ShortcutOverride:
        event->accept(); // no shortcut: the key arrives as a key press, below
        return true;
    case QEvent::KeyPress:
        unblank();
        return true;
    case QEvent::KeyRelease:
        return true; // the release of the key that unblanked: nothing to do
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick:
        if (watched->isWidgetType() && static_cast<QWidget *>(watched)->window() == window()) {
            unblank();
            return true;
        }
        return false;
    default:
        return false;
    }
}

void ScreenBlank::paintEvent(QPaintEvent *)
{
    QPainter(this).fillRect(rect(), Qt::black);
}

} // namespace lb
