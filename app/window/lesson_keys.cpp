#include "lesson_keys.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QWidget>

namespace lb {

LessonKeys::LessonKeys(QWidget *window, QAction *next, QAction *previous, QAction *first,
                       QAction *last)
    : QObject(window), m_window(window), m_next(next), m_previous(previous), m_first(first),
      m_last(last)
{
}

LessonKeys::~LessonKeys()
{
    if (m_active)
        qApp->removeEventFilter(this);
}

QList<QKeySequence> LessonKeys::nextKeys()
{
    return {QKeySequence(Qt::Key_PageDown), QKeySequence(Qt::Key_Right),
            QKeySequence(Qt::Key_Space), QKeySequence(Qt::Key_N)};
}

QList<QKeySequence> LessonKeys::previousKeys()
{
    return {QKeySequence(Qt::Key_PageUp), QKeySequence(Qt::Key_Left),
            QKeySequence(Qt::Key_Backspace), QKeySequence(Qt::Key_P)};
}

QList<QKeySequence> LessonKeys::allKeys() const
{
    return nextKeys() + previousKeys() +
           QList<QKeySequence>{QKeySequence(Qt::Key_Home), QKeySequence(Qt::Key_End)};
}

void LessonKeys::setActive(bool on)
{
    if (on == m_active)
        return;
    m_active = on;
    if (on) {
        // Two actions on one key would both stay silent (Qt calls it ambiguous): the other
        // action moves to Shift and the same key, which nothing else here uses.
        const QList<QKeySequence> taken = allKeys();
        const QList<QAction *> ours{m_next, m_previous, m_first, m_last};
        for (QAction *action : m_window->findChildren<QAction *>()) {
            if (ours.contains(action))
                continue;
            const QList<QKeySequence> keys = action->shortcuts();
            QList<QKeySequence> moved;
            bool clashes = false;
            for (const QKeySequence &key : keys) {
                if (taken.contains(key) && key.count() == 1) {
                    clashes = true;
                    moved << QKeySequence(QKeyCombination(
                        key[0].keyboardModifiers() | Qt::ShiftModifier, key[0].key()));
                } else {
                    moved << key;
                }
            }
            if (!clashes)
                continue;
            m_moved.push_back({action, keys});
            action->setShortcuts(moved);
        }
        m_next->setShortcuts(nextKeys());
        m_previous->setShortcuts(previousKeys());
        m_first->setShortcut(QKeySequence(Qt::Key_Home));
        m_last->setShortcut(QKeySequence(Qt::Key_End));
        qApp->installEventFilter(this);
    } else {
        qApp->removeEventFilter(this);
        for (QAction *action : {m_next, m_previous, m_first, m_last})
            action->setShortcuts({});
        for (const Moved &m : m_moved)
            if (m.action)
                m.action->setShortcuts(m.keys);
        m_moved.clear();
    }
}

bool LessonKeys::isTextField(const QWidget *widget)
{
    if (!widget)
        return false;
    if (const auto *combo = qobject_cast<const QComboBox *>(widget))
        return combo->isEditable();
    if (qobject_cast<const QLineEdit *>(widget) || qobject_cast<const QAbstractSpinBox *>(widget) ||
        qobject_cast<const QPlainTextEdit *>(widget) || qobject_cast<const QTextEdit *>(widget))
        return true;
    // QScintilla's editor is a QAbstractScrollArea of its own kind: known by its class name
    // (the focus may be on its viewport).
    for (const QWidget *w = widget; w; w = w->parentWidget())
        if (w->inherits("QsciScintillaBase"))
            return true;
    return false;
}

bool LessonKeys::eventFilter(QObject *watched, QEvent *event)
{
    // Before a key becomes a shortcut, the widget with the focus is asked whether it wants it
    // (ShortcutOverride): a text field gets the lesson's keys as the keys they are.
    if (event->type() == QEvent::ShortcutOverride && watched->isWidgetType()) {
        auto *key = static_cast<QKeyEvent *>(event);
        auto *widget = static_cast<QWidget *>(watched);
        if (isTextField(widget) && allKeys().contains(QKeySequence(key->keyCombination()))) {
            event->accept();
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace lb
