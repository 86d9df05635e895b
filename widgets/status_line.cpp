#include "status_line.h"

#include <QHBoxLayout>
#include <QMainWindow>
#include <QPainter>
#include <QStatusBar>

namespace lb {

ElidedLabel::ElidedLabel(QWidget *parent) : QFrame(parent)
{
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
}

void ElidedLabel::setText(const QString &text)
{
    if (text == m_text)
        return;
    m_text = text;
    updateToolTip();
    update();
}

void ElidedLabel::setFullText(const QString &toolTip)
{
    m_fullText = toolTip;
    updateToolTip();
}

bool ElidedLabel::isElided() const
{
    return fontMetrics().horizontalAdvance(m_text) > contentsRect().width();
}

QSize ElidedLabel::sizeHint() const
{
    return QSize(fontMetrics().horizontalAdvance(m_text) + 8, fontMetrics().height() + 4);
}

QSize ElidedLabel::minimumSizeHint() const
{
    return QSize(fontMetrics().horizontalAdvance(QStringLiteral("M...")), fontMetrics().height());
}

void ElidedLabel::paintEvent(QPaintEvent *event)
{
    QFrame::paintEvent(event);
    QPainter painter(this);
    const QRect r = contentsRect();
    painter.drawText(r, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine,
                     fontMetrics().elidedText(m_text, Qt::ElideRight, r.width()));
}

void ElidedLabel::updateToolTip()
{
    setToolTip(m_fullText.isEmpty() ? m_text : m_fullText);
}

StatusLine::StatusLine(QWidget *parent) : QWidget(parent)
{
    m_row = new QHBoxLayout(this);
    m_row->setContentsMargins(0, 0, 0, 0);
    m_row->setSpacing(12);
    m_program = new ElidedLabel(this);
    m_message = new ElidedLabel(this);
    m_mesh = new ElidedLabel(this);
    m_driver = new ElidedLabel(this);
    // Shares of the width: the program and the messages matter most; the driver least.
    m_row->addWidget(m_program, 4);
    m_row->addWidget(m_message, 4);
    m_row->addWidget(m_mesh, 2);
    m_row->addWidget(m_driver, 2);
    m_clear.setSingleShot(true);
    connect(&m_clear, &QTimer::timeout, this, [this] { showMessage({}, 0); });
    m_message->hide(); // no message: the program's line takes the room
}

void StatusLine::setProgressWidget(QWidget *progress)
{
    m_row->insertWidget(m_row->indexOf(m_mesh), progress, 0);
}

void StatusLine::showMessage(const QString &text, int milliseconds)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
    // A message is news and goes away by itself: while it shows, it has the most room (the
    // program's line, the mesh and the driver are in their tooltips).
    const bool news = !text.isEmpty();
    m_row->setStretchFactor(m_program, news ? 3 : 4);
    m_row->setStretchFactor(m_message, news ? 6 : 4);
    m_row->setStretchFactor(m_driver, news ? 1 : 2);
    if (milliseconds > 0)
        m_clear.start(milliseconds);
    else
        m_clear.stop();
    emit messageChanged(text);
}

void showStatusMessage(QMainWindow *window, const QString &text, int milliseconds)
{
    if (auto *line = window->statusBar()->findChild<StatusLine *>())
        line->showMessage(text, milliseconds);
    else
        window->statusBar()->showMessage(text, milliseconds);
}

} // namespace lb
