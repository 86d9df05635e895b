#include "load_progress.h"

#include "status_line.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>

namespace lb {

LoadProgress::LoadProgress(QWidget *parent) : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_label = new ElidedLabel(this);
    m_bar = new QProgressBar(this);
    m_bar->setRange(0, 1000);
    m_bar->setTextVisible(false);
    sizeToFont();
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setToolTip(tr("Stop loading: the import helper is stopped, the current mesh stays"));
    row->addWidget(m_label);
    row->addWidget(m_bar);
    row->addWidget(m_cancel);
    connect(m_cancel, &QPushButton::clicked, this, &LoadProgress::cancelRequested);
    m_showTimer.setSingleShot(true);
    m_showTimer.setInterval(kShowAfterMs);
    connect(&m_showTimer, &QTimer::timeout, this, &QWidget::show);
    hide();
}

void LoadProgress::sizeToFont()
{
    // Fixed widths in characters: they grow with the UI scale and never with the text.
    const int character = fontMetrics().averageCharWidth();
    m_label->setFixedWidth(character * 28);
    m_bar->setFixedWidth(character * 18);
}

void LoadProgress::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange)
        sizeToFont();
}

void LoadProgress::start(const QString &name)
{
    m_name = name;
    m_label->setText(tr("Loading %1...").arg(name));
    m_bar->setRange(0, 0); // busy until the helper reports how far it is
    m_bar->setValue(0);
    m_showTimer.start();
}

void LoadProgress::setProgress(double fraction, const QString &stage)
{
    m_bar->setRange(0, 1000);
    m_bar->setValue(int(fraction * 1000.0));
    m_label->setText(tr("Loading %1: %2").arg(m_name, stage));
}

void LoadProgress::stop()
{
    m_showTimer.stop();
    hide();
}

} // namespace lb
