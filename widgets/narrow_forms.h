#pragma once
// Forms that narrow instead of scrolling sideways: a panel at 200% in the column a 1024-pixel
// projector leaves beside the view (issue 49, item 14). A row of boxes stands one under another
// and a check box's text wraps where the form is narrower than they need side by side; only
// in panels allowed to (setFormsMayStack): elsewhere the form asks for the width it needs, as
// a QHBoxLayout and a QCheckBox do, and the window gives it.

#include <QCheckBox>
#include <QComboBox>
#include <QLayout>
#include <QList>

namespace lb {

// Its widgets side by side where they fit, else one under another.
class WrapRow : public QLayout
{
    Q_OBJECT
public:
    enum class Room {
        Shared, // the boxes of a vector: equals, the row's width shared out among them
        Left,   // switches and buttons: each its own width, from the left; the room over goes
                // to the widgets whose policy expands
    };
    explicit WrapRow(Room room = Room::Shared);
    ~WrapRow() override;

    void setMayStack(bool on);

    void addItem(QLayoutItem *item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem *itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem *takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return Qt::Horizontal; }
    bool hasHeightForWidth() const override { return m_mayStack; }
    int heightForWidth(int width) const override;
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect &rect) override;

private:
    int sideBySideMinimum() const; // the widgets' minimum widths with the spacing between
    bool stacks(int width) const { return m_mayStack && width < sideBySideMinimum(); }
    int gap() const;

    QList<QLayoutItem *> m_items;
    Room m_room;
    bool m_mayStack = false;
};

// A check box whose text wraps where the form is narrower than it.
class WrapCheckBox : public QCheckBox
{
    Q_OBJECT
public:
    explicit WrapCheckBox(const QString &text, QWidget *parent = nullptr);

    void setMayWrap(bool on);

    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override { return m_mayWrap; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    bool hitButton(const QPoint &pos) const override;

private:
    int indicatorWidth() const; // the box and the space before the text
    QSizePolicy m_linePolicy;   // QCheckBox's own
    bool m_mayWrap = false;
};

// A combo box narrower than its choice's words ends them with "…" (the style cuts them
// off mid-letter: "World: fixed in the sce"); the list it opens shows them whole.
class ElidingComboBox : public QComboBox
{
    Q_OBJECT
public:
    using QComboBox::QComboBox;
    QString shownText() const; // the current choice as drawn

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QRect textField(const QStyleOptionComboBox &option) const;
};

// Lets every WrapRow and WrapCheckBox under `panel` stack and wrap (or not).
void setFormsMayStack(QWidget *panel, bool on);

} // namespace lb
