#include "lesson_bar.h"

#include "status_line.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QStyle>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>
#include <vector>

namespace lb {

namespace {

QToolButton *barButton(const QString &text, const QString &tip, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(tip);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    // The keys step; a click must not leave the focus in the bar (Space would press it).
    button->setFocusPolicy(Qt::NoFocus);
    return button;
}

} // namespace

LessonBar::LessonBar(QWidget *parent) : QFrame(parent)
{
    setObjectName("lessonBar");
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    m_previous =
        barButton(QString::fromUtf8("\u25c0"), tr("The previous step (PageUp, Left)"), this);
    m_next =
        barButton(QString::fromUtf8("\u25b6"), tr("The next step (PageDown, Right, Space)"), this);
    m_position = new QLabel(this);
    m_position->setObjectName("lessonPosition");
    m_title = new QLabel(this);
    m_title->setTextFormat(Qt::RichText);
    m_title->setWordWrap(true);
    m_caption = new QLabel(this);
    m_caption->setTextFormat(Qt::RichText);
    m_caption->setWordWrap(true);
    m_caption->setTextInteractionFlags(Qt::NoTextInteraction);
    m_reset = barButton(tr("Reset Step"),
                        tr("This step as the lesson has it: your changes to it "
                           "are set aside"),
                        this);
    m_menu = barButton(QString::fromUtf8("\u2630"),
                       tr("The Lesson menu: add, rename, caption, move and save steps"), this);
    m_menu->setPopupMode(QToolButton::InstantPopup);
    // The buttons show symbols (◀ ▶ ☰ ✕), the same in every language; their tooltips say it.
    m_close =
        barButton(QString::fromUtf8("\u2715"), tr("Close the lesson (the scene stays)"), this);
    m_close->setObjectName("lessonClose");

    // Three rows: where the class is and the buttons, the title, then the caption across the
    // whole width (beside the buttons both wrapped to a word a line). A long caption scrolls
    // in at most a few lines, so the view keeps its height.
    m_captionArea = new QScrollArea(this);
    m_captionArea->setWidget(m_caption);
    m_captionArea->setWidgetResizable(true);
    m_captionArea->setFrameShape(QFrame::NoFrame);
    m_captionArea->setFocusPolicy(Qt::NoFocus);
    m_captionArea->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *top = new QHBoxLayout;
    top->addWidget(m_previous);
    top->addWidget(m_position);
    top->addWidget(m_next);
    m_message = new ElidedLabel(this);
    m_message->setMinimumWidth(0);
    m_message->hide();
    top->addWidget(m_message, 1);
    top->addStretch(0);
    top->addWidget(m_reset);
    top->addWidget(m_menu);
    top->addWidget(m_close);
    auto *rows = new QVBoxLayout(this);
    rows->setContentsMargins(6, 4, 6, 4);
    rows->setSpacing(2);
    rows->addLayout(top);
    rows->addWidget(m_title);
    rows->addWidget(m_captionArea);

    connect(m_previous, &QToolButton::clicked, this, &LessonBar::previousRequested);
    connect(m_next, &QToolButton::clicked, this, &LessonBar::nextRequested);
    connect(m_reset, &QToolButton::clicked, this, &LessonBar::resetRequested);
    connect(m_close, &QToolButton::clicked, this, &LessonBar::closeRequested);
}

void LessonBar::setMenu(QMenu *menu)
{
    m_menu->setMenu(menu);
}

void LessonBar::showStep(int index, int count, const QString &title, const QString &caption,
                         const QString &error)
{
    //: where the class is in the lesson: step %1 of %2 steps
    m_position->setText(tr("Step %1 of %2").arg(index + 1).arg(count));
    m_title->setText("<b>" + title.toHtmlEscaped() + "</b>");
    m_previous->setEnabled(index > 0);
    m_next->setEnabled(index + 1 < count);
    m_reset->setEnabled(error.isEmpty());
    m_captionText = caption;
    m_error = error;
    m_captionArea->setVisible(!caption.trimmed().isEmpty() || !error.isEmpty());
    showCaption();
}

void LessonBar::showCaption()
{
    if (!m_error.isEmpty()) {
        // The reason in the place of the caption, where the class looks: the scene stayed.
        m_caption->setText(QString("<span style=\"color:#c0392b\">%1</span>")
                               .arg(tr("This step cannot be shown; the scene is as it was. %1")
                                        .arg(m_error)
                                        .toHtmlEscaped()));
        fitCaption();
        return;
    }
    m_caption->setText(captionHtml(m_captionText, font()));
    fitCaption();
}

void LessonBar::setMessage(const QString &text)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

QString LessonBar::message() const
{
    return m_message->isVisible() ? m_message->text() : QString();
}

void LessonBar::setVisible(bool visible)
{
    const bool was = isVisibleTo(parentWidget());
    QFrame::setVisible(visible);
    if (was != visible)
        emit visibilityChanged(visible);
}

void LessonBar::fitCaption()
{
    const int width = m_captionArea->viewport()->width();
    const int needed = m_caption->heightForWidth(width > 0 ? width : this->width());
    // A fifth of the window: 9 lines at 100% on a 768-line screen (a step's caption whole in
    // the column between the panels), 4 at 200%; whole lines.
    const int line = std::max(fontMetrics().lineSpacing(), 1);
    const int most = line * std::max(kCaptionLines, window()->height() / 5 / line);
    m_captionArea->setFixedHeight(std::max(0, std::min(needed, most)));
}

void LessonBar::resizeEvent(QResizeEvent *event)
{
    QFrame::resizeEvent(event);
    fitCaption();
}

QString LessonBar::captionHtml(const QString &markdown, const QFont &font)
{
    QTextDocument document;
    document.setDefaultFont(font);
    // Raw HTML stays text; an image would be read from a path the lesson names (a FIFO, a
    // huge file) when the label lays it out, so each one is cut out before anyone does.
    document.setMarkdown(markdown,
                         QTextDocument::MarkdownFeatures(QTextDocument::MarkdownDialectGitHub |
                                                         QTextDocument::MarkdownNoHTML));
    std::vector<std::pair<int, int>> images; // position, length
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it)
            if (it.fragment().isValid() && it.fragment().charFormat().isImageFormat())
                images.emplace_back(it.fragment().position(), it.fragment().length());
    for (auto image = images.rbegin(); image != images.rend(); ++image) { // the last first
        QTextCursor cursor(&document);
        cursor.setPosition(image->first);
        cursor.setPosition(image->first + image->second, QTextCursor::KeepAnchor);
        //: in a lesson's caption, where the markdown had an image (never shown there)
        cursor.insertText(tr("[picture]"), QTextCharFormat());
    }
    return document.toHtml();
}

void LessonBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange)
        showCaption(); // the caption's HTML names its font size
    QFrame::changeEvent(event);
}

} // namespace lb
