#pragma once
// The keys of a lesson: a presenter's clicker and the keyboard step through it (PageDown,
// Right, Space, N forward; PageUp, Left, Backspace, P back; Home and End). While a lesson is
// open they are the lesson's: a window action that had one of them (Auto-rotate on Space,
// Show Normals on N, Perspective / Orthographic on P) takes Shift with it meanwhile, so the
// menus and the F1 list show the key that works; closing the lesson gives them back. A text
// field with the focus (the shader editor, a number box, a line edit) keeps its keys.

#include <QKeySequence>
#include <QObject>
#include <QPointer>

#include <vector>

class QAction;
class QWidget;

namespace lb {

class LessonKeys : public QObject
{
    Q_OBJECT
public:
    // `window`: whose actions give up their keys; `next`, `previous`, `first`, `last`: the
    // lesson's actions.
    LessonKeys(QWidget *window, QAction *next, QAction *previous, QAction *first, QAction *last);
    ~LessonKeys() override;

    void setActive(bool on);
    bool isActive() const { return m_active; }
    static QList<QKeySequence> nextKeys();
    static QList<QKeySequence> previousKeys();
    // Whether `widget` types what it is given (and so keeps the lesson's keys).
    static bool isTextField(const QWidget *widget);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Moved
    {
        QPointer<QAction> action;
        QList<QKeySequence> keys; // its own, given back on close
    };
    QList<QKeySequence> allKeys() const;

    QWidget *m_window;
    QAction *m_next, *m_previous, *m_first, *m_last;
    std::vector<Moved> m_moved;
    bool m_active = false;
};

} // namespace lb
