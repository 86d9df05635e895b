#pragma once
// The lesson bar under the view: where the class is in the lesson ("Step 3 of 12"), the
// step's title and caption (markdown), the buttons to go back and forward, Reset step, the
// lesson's menu and Close. It shows; the window's LessonActions decides.

#include <QFrame>

class QLabel;
class QMenu;
class QScrollArea;
class QToolButton;

namespace lb {

class ElidedLabel;

class LessonBar : public QFrame
{
    Q_OBJECT
public:
    explicit LessonBar(QWidget *parent = nullptr);

    // `index` from 0; `error`, when not empty, is shown instead of the caption.
    void showStep(int index, int count, const QString &title, const QString &caption,
                  const QString &error);
    void setMenu(QMenu *menu); // the lesson's authoring menu, behind the bar's menu button
    // The window's last message in the bar's first row, beside the buttons (presentation mode
    // hides the status line under the bar: its empty row took the caption's room); empty:
    // none.
    void setMessage(const QString &text);
    QString message() const;
    void setVisible(bool visible) override;

    QLabel *positionLabel() const { return m_position; }
    QLabel *titleLabel() const { return m_title; }
    QLabel *captionLabel() const { return m_caption; }
    QToolButton *previousButton() const { return m_previous; }
    QToolButton *nextButton() const { return m_next; }
    QToolButton *resetButton() const { return m_reset; }
    QToolButton *closeButton() const { return m_close; }

    // A caption's markdown as the bar shows it, in rich text: images and HTML are left out
    // (a caption must not make the window read files), at `font`'s size.
    static QString captionHtml(const QString &markdown, const QFont &font);

signals:
    void previousRequested();
    void nextRequested();
    void resetRequested();
    void closeRequested();
    void visibilityChanged(bool visible);

protected:
    void changeEvent(QEvent *event) override; // the UI scale: the caption follows the font
    void resizeEvent(QResizeEvent *event) override;

private:
    // The caption takes the lines its text needs, up to a fifth of the window's height and at
    // least this many; more scrolls.
    static constexpr int kCaptionLines = 3;
    void showCaption();
    void fitCaption(); // the caption's height for its text at the bar's width

    QLabel *m_position, *m_title, *m_caption;
    ElidedLabel *m_message;
    QScrollArea *m_captionArea;
    QToolButton *m_previous, *m_next, *m_reset, *m_menu, *m_close;
    QString m_captionText, m_error;
};

} // namespace lb
