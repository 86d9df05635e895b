#pragma once
// The status bar's fixed places: the program (what draws), the last message, the load's
// progress with its Cancel button, the mesh and the driver. Each text is elided to its place
// with the whole text in the tooltip, so a long message never runs into its neighbour and the
// Cancel button never moves while the progress text changes.

#include <QFrame>
#include <QTimer>

class QHBoxLayout;
class QMainWindow;

namespace lb {

// A one-line label that elides its text to the width it is given (never asks for more) and
// shows the whole text as its tooltip.
class ElidedLabel : public QFrame
{
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget *parent = nullptr);
    QString text() const { return m_text; }
    void setText(const QString &text);
    // The tooltip shown instead of the text (the mesh's long summary); empty: the text.
    void setFullText(const QString &toolTip);
    bool isElided() const;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    void updateToolTip();
    QString m_text;
    QString m_fullText;
};

class StatusLine : public QWidget
{
    Q_OBJECT
public:
    explicit StatusLine(QWidget *parent = nullptr);

    ElidedLabel *programLabel() const { return m_program; }
    ElidedLabel *messageLabel() const { return m_message; }
    ElidedLabel *meshLabel() const { return m_mesh; }
    ElidedLabel *driverLabel() const { return m_driver; }
    // The load's progress row, placed between the message and the mesh.
    void setProgressWidget(QWidget *progress);

    void setProgram(const QString &text) { m_program->setText(text); }
    // Shown for `milliseconds` (0: until the next message).
    void showMessage(const QString &text, int milliseconds = 8000);
    QString message() const { return m_message->text(); }

signals:
    void messageChanged(const QString &text); // empty: the message went

private:
    QHBoxLayout *m_row;
    ElidedLabel *m_program;
    ElidedLabel *m_message;
    ElidedLabel *m_mesh;
    ElidedLabel *m_driver;
    QTimer m_clear;
};

// The window's status line (a message there), or the status bar's own message when the
// window has none.
void showStatusMessage(QMainWindow *window, const QString &text, int milliseconds = 8000);

} // namespace lb
