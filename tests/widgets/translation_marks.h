#pragma once
// What the widgets show, read through a translator that marks everything it is asked: each
// text that goes through tr() / QCoreApplication::translate comes back as «CONTEXT|SOURCE»
// (marking_translator.h; arg() and Qt's %n fill the placeholders in as usual), and the
// translator keeps a list of what it was asked. A word a user reads outside every mark did
// not go through Qt's translation system; a mark in the QObject context was made by
// QObject::tr in a free function, where a translator cannot tell whose words they are.

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSpinBox>
#include <QStringList>
#include <QTabBar>
#include <QTextDocumentFragment>
#include <QTranslator>
#include <QTreeWidget>

#include "marking_translator.h"

#include <set>
#include <vector>

namespace lb::test {

struct Asked
{
    QString context, source, disambiguation;
    int n = -1;
};

// The project's marking translator (marking_translator.h), which also keeps what it was asked.
class RecordingTranslator : public MarkingTranslator
{
public:
    QString translate(const char *context, const char *source, const char *disambiguation,
                      int n) const override
    {
        if (source)
            m_asked.push_back({QString::fromUtf8(context), QString::fromUtf8(source),
                               QString::fromUtf8(disambiguation), n});
        return MarkingTranslator::translate(context, source, disambiguation, n);
    }
    // Whether `source` was asked in `context` (with `disambiguation`, when given).
    bool asked(const QString &context, const QString &source,
               const QString &disambiguation = QString()) const
    {
        for (const Asked &a : m_asked)
            if (a.context == context && a.source == source &&
                (disambiguation.isEmpty() || a.disambiguation == disambiguation))
                return true;
        return false;
    }
    const std::vector<Asked> &askedAll() const { return m_asked; }

private:
    mutable std::vector<Asked> m_asked;
};

// The course's symbols and GLSL's words, which no language translates.
inline const std::set<QString> &symbols()
{
    static const std::set<QString> words{
        "N",    "L",    "V",   "H",     "R",   "P",    "I",   "D",    "Ia",    "Id",
        "Is",   "Ka",   "Kd",  "Ks",    "x",   "y",    "z",   "w",    "X",     "Y",
        "Z",    "n",    "d",   "kc",    "kl",  "kq",   "G",   "B",    "a",     "att",
        "spot", "base", "max", "float", "int", "bool", "vec", "ivec", "\u03a3"};
    return words;
}

// What is wrong with `text` as a user reads it: the words outside every mark that are neither
// symbols nor in `data` (names the user or a file gave), and the marks of a context that is
// neither lightbench's (lb::) nor one of Qt's own classes. Empty: all of it is translatable.
inline QStringList problems(const QString &text, const std::set<QString> &data = {})
{
    QStringList found;
    int depth = 0;
    QString word;
    const auto endWord = [&] {
        if (!word.isEmpty() && depth == 0 && !symbols().count(word) && !data.count(word))
            found << "unmarked \"" + word + "\" in: " + text;
        word.clear();
    };
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (c == QChar(0x00ab)) {
            endWord();
            // No bar: the text was cut inside a mark (an accessible name made of the part of
            // a tooltip before its first colon), its context unknown.
            const qsizetype bar = text.indexOf('|', i);
            const QString context = bar < 0 ? QString() : text.mid(i + 1, bar - i - 1);
            if (bar >= 0 && !context.startsWith("lb::") &&
                (context == "QObject" || !context.startsWith('Q')))
                found << "context \"" + context + "\" in: " + text;
            ++depth;
        } else if (c == QChar(0x00bb)) {
            endWord();
            depth = std::max(0, depth - 1);
        } else if (c.isLetter()) {
            word += c;
        } else {
            endWord();
        }
    }
    endWord();
    return found;
}

// Whether `text` is one translated sentence: one mark from its first character to its last
// (arguments may be marked inside it), not pieces put side by side.
inline bool oneSentence(const QString &text)
{
    const QString t = text.trimmed();
    if (!t.startsWith(QChar(0x00ab)) || !t.endsWith(QChar(0x00bb)))
        return false;
    int depth = 0;
    for (qsizetype i = 0; i < t.size(); ++i) {
        if (t[i] == QChar(0x00ab))
            ++depth;
        else if (t[i] == QChar(0x00bb) && --depth == 0 && i + 1 < t.size())
            return false; // the first mark closes before the end
    }
    return depth == 0;
}

// Every text a user may read in `root` and the widgets inside it: titles, labels (rich text as
// shown), buttons, tooltips, accessible names, combo and list entries, tabs, tree headers and
// rows, placeholders, spin box prefixes and suffixes, menu entries.
inline QStringList shownTexts(QWidget *root)
{
    QStringList texts{root->windowTitle()};
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : widgets) {
        texts << w->toolTip() << w->accessibleName();
        if (auto *label = qobject_cast<QLabel *>(w))
            texts << QTextDocumentFragment::fromHtml(label->text()).toPlainText();
        if (auto *button = qobject_cast<QAbstractButton *>(w))
            texts << button->text();
        if (auto *combo = qobject_cast<QComboBox *>(w))
            for (int i = 0; i < combo->count(); ++i)
                texts << combo->itemText(i) << combo->itemData(i, Qt::ToolTipRole).toString();
        if (auto *list = qobject_cast<QListWidget *>(w))
            for (int i = 0; i < list->count(); ++i)
                texts << list->item(i)->text() << list->item(i)->toolTip();
        if (auto *tabs = qobject_cast<QTabBar *>(w))
            for (int i = 0; i < tabs->count(); ++i)
                texts << tabs->tabText(i) << tabs->tabToolTip(i);
        if (auto *tree = qobject_cast<QTreeWidget *>(w)) {
            QList<QTreeWidgetItem *> items{tree->headerItem()};
            for (int i = 0; i < tree->topLevelItemCount(); ++i)
                items << tree->topLevelItem(i);
            for (QTreeWidgetItem *item : items)
                for (int c = 0; c < tree->columnCount(); ++c)
                    texts << item->text(c) << item->toolTip(c);
        }
        if (auto *edit = qobject_cast<QLineEdit *>(w))
            texts << edit->placeholderText();
        if (auto *edit = qobject_cast<QPlainTextEdit *>(w))
            texts << edit->placeholderText();
        if (auto *spin = qobject_cast<QSpinBox *>(w))
            texts << spin->prefix() << spin->suffix() << spin->specialValueText();
        if (auto *spin = qobject_cast<QDoubleSpinBox *>(w))
            texts << spin->prefix() << spin->suffix() << spin->specialValueText();
        if (auto *menu = qobject_cast<QMenu *>(w))
            for (QAction *action : menu->actions())
                texts << action->text() << action->toolTip();
    }
    texts.removeAll(QString());
    return texts;
}

// problems() of every text shown in `root`.
inline QStringList problemsIn(QWidget *root, const std::set<QString> &data = {})
{
    QStringList found;
    for (const QString &text : shownTexts(root))
        found << problems(text, data);
    return found;
}

// The words (letters only) of `text`, added to `words`: data a test put in, allowed where it
// is shown.
inline std::set<QString> wordsOf(const QString &text, std::set<QString> words = {})
{
    QString word;
    for (QChar c : text + ' ') {
        if (c.isLetter()) {
            word += c;
        } else if (!word.isEmpty()) {
            words.insert(word);
            word.clear();
        }
    }
    return words;
}

} // namespace lb::test
