#include "narrow_forms.h"

#include <QFormLayout>
#include <QPaintEvent>
#include <QStyle>
#include <QStyleOptionButton>
#include <QStyleOptionComboBox>
#include <QStylePainter>
#include <QVariant>
#include <QWidget>

#include <algorithm>

namespace lb {

WrapRow::WrapRow(Room room) : m_room(room)
{
    setContentsMargins(0, 0, 0, 0); // a row inside a form, as a QHBoxLayout there
}

WrapRow::~WrapRow()
{
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

void WrapRow::setMayStack(bool on)
{
    if (on == m_mayStack)
        return;
    m_mayStack = on;
    invalidate();
}

void WrapRow::addItem(QLayoutItem *item)
{
    m_items.append(item);
}

QLayoutItem *WrapRow::takeAt(int index)
{
    return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

int WrapRow::gap() const
{
    if (spacing() >= 0)
        return spacing();
    const QWidget *widget = parentWidget();
    return widget
               ? widget->style()->pixelMetric(QStyle::PM_LayoutHorizontalSpacing, nullptr, widget)
               : 6;
}

int WrapRow::sideBySideMinimum() const
{
    int width = 0;
    int shown = 0;
    for (const QLayoutItem *item : m_items)
        if (!item->isEmpty()) {
            width += item->minimumSize().width();
            ++shown;
        }
    return width + std::max(shown - 1, 0) * gap();
}

QSize WrapRow::minimumSize() const
{
    int widest = 0;
    int tallest = 0;
    int stackedHeight = 0;
    int shown = 0;
    for (const QLayoutItem *item : m_items)
        if (!item->isEmpty()) {
            const QSize s = item->minimumSize();
            widest = std::max(widest, s.width());
            tallest = std::max(tallest, s.height());
            stackedHeight += item->sizeHint().height();
            ++shown;
        }
    if (m_mayStack)
        return {widest, stackedHeight + std::max(shown - 1, 0) * gap()};
    return {sideBySideMinimum(), tallest};
}

QSize WrapRow::sizeHint() const
{
    int width = 0;
    int height = 0;
    int shown = 0;
    for (const QLayoutItem *item : m_items)
        if (!item->isEmpty()) {
            const QSize s = item->sizeHint();
            width += s.width();
            height = std::max(height, s.height());
            ++shown;
        }
    return {width + std::max(shown - 1, 0) * gap(), height};
}

int WrapRow::heightForWidth(int width) const
{
    if (!stacks(width))
        return sizeHint().height();
    int height = 0;
    int shown = 0;
    for (const QLayoutItem *item : m_items)
        if (!item->isEmpty()) {
            height +=
                item->hasHeightForWidth() ? item->heightForWidth(width) : item->sizeHint().height();
            ++shown;
        }
    return height + std::max(shown - 1, 0) * gap();
}

void WrapRow::setGeometry(const QRect &rect)
{
    QLayout::setGeometry(rect);
    std::vector<QLayoutItem *> shown;
    for (QLayoutItem *item : m_items)
        if (!item->isEmpty())
            shown.push_back(item);
    if (shown.empty())
        return;
    if (stacks(rect.width())) {
        int y = rect.y();
        for (QLayoutItem *item : shown) {
            const bool fills =
                m_room == Room::Shared || (item->expandingDirections() & Qt::Horizontal);
            const int w = fills ? rect.width() : std::min(item->sizeHint().width(), rect.width());
            const int h =
                item->hasHeightForWidth() ? item->heightForWidth(w) : item->sizeHint().height();
            item->setGeometry(QRect(rect.x(), y, w, h));
            y += h + gap();
        }
        return;
    }
    // Side by side: each its hint, the room over shared alike (Shared) or among the items that
    // expand (Left), or, short of room, each giving up its share of what it has above its
    // minimum.
    const int room = rect.width() - int(shown.size() - 1) * gap();
    std::vector<int> widths;
    int hinted = 0;
    int above = 0;
    for (QLayoutItem *item : shown) {
        widths.push_back(item->sizeHint().width());
        hinted += widths.back();
        above += widths.back() - item->minimumSize().width();
    }
    const int spare = room - hinted;
    int growing = 0; // what takes the room over (Left: the items that expand)
    for (QLayoutItem *item : shown)
        growing += m_room == Room::Shared || (item->expandingDirections() & Qt::Horizontal);
    for (std::size_t i = 0; i < shown.size(); ++i) {
        if (spare >= 0 && growing > 0 &&
            (m_room == Room::Shared || (shown[i]->expandingDirections() & Qt::Horizontal)))
            widths[i] += spare / growing;
        else if (above > 0)
            widths[i] -=
                int(qint64(-spare) * (widths[i] - shown[i]->minimumSize().width()) / above);
    }
    int x = rect.x();
    for (std::size_t i = 0; i < shown.size(); ++i) {
        shown[i]->setGeometry(QRect(x, rect.y(), widths[i], rect.height()));
        x += widths[i] + gap();
    }
}

WrapCheckBox::WrapCheckBox(const QString &text, QWidget *parent)
    : QCheckBox(text, parent), m_linePolicy(sizePolicy())
{
}

void WrapCheckBox::setMayWrap(bool on)
{
    if (on == m_mayWrap)
        return;
    m_mayWrap = on;
    // A QCheckBox is no narrower than its line nor taller; wrapping, it is both.
    QSizePolicy policy = m_linePolicy;
    if (on) {
        policy.setHorizontalPolicy(QSizePolicy::Preferred);
        policy.setVerticalPolicy(QSizePolicy::Minimum);
        policy.setHeightForWidth(true);
    }
    setSizePolicy(policy);
    updateGeometry();
    update();
}

int WrapCheckBox::indicatorWidth() const
{
    QStyleOptionButton option;
    initStyleOption(&option);
    return style()->pixelMetric(QStyle::PM_IndicatorWidth, &option, this) +
           style()->pixelMetric(QStyle::PM_CheckBoxLabelSpacing, &option, this);
}

QSize WrapCheckBox::minimumSizeHint() const
{
    if (!m_mayWrap)
        return QCheckBox::minimumSizeHint();
    // The longest word beside the box: no word is broken.
    int word = 0;
    QString plain = text();
    plain.remove('&');
    for (const QString &w : plain.split(' ', Qt::SkipEmptyParts))
        word = std::max(word, fontMetrics().horizontalAdvance(w));
    return {indicatorWidth() + word + 4, QCheckBox::sizeHint().height()};
}

int WrapCheckBox::heightForWidth(int width) const
{
    const QSize single = QCheckBox::sizeHint();
    if (!m_mayWrap || width >= single.width())
        return single.height();
    const QRect text =
        fontMetrics().boundingRect(QRect(0, 0, std::max(width - indicatorWidth(), 1), 100000),
                                   Qt::TextWordWrap | Qt::TextShowMnemonic, this->text());
    return std::max(single.height(), text.height() + single.height() - fontMetrics().height());
}

void WrapCheckBox::paintEvent(QPaintEvent *event)
{
    if (!m_mayWrap || width() >= QCheckBox::sizeHint().width()) {
        QCheckBox::paintEvent(event);
        return;
    }
    QStylePainter painter(this);
    QStyleOptionButton option;
    initStyleOption(&option);
    const int flags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap | Qt::TextShowMnemonic;
    const int left = indicatorWidth();
    QRect text = fontMetrics().boundingRect(QRect(left, 0, std::max(width() - left, 1), 100000),
                                            flags, option.text);
    text.moveTop((height() - text.height()) / 2);
    // The box beside the first line, where a reader starts.
    QStyleOptionButton box = option;
    box.text.clear();
    const int side = style()->pixelMetric(QStyle::PM_IndicatorHeight, &option, this);
    box.rect = QRect(0, text.top() + (fontMetrics().height() - side) / 2,
                     style()->pixelMetric(QStyle::PM_IndicatorWidth, &option, this), side);
    painter.drawPrimitive(QStyle::PE_IndicatorCheckBox, box);
    style()->drawItemText(&painter, text, flags, option.palette, isEnabled(), option.text,
                          QPalette::WindowText);
    if (option.state & QStyle::State_HasFocus) {
        QStyleOptionFocusRect focus;
        focus.initFrom(this);
        focus.rect = text.adjusted(-2, -1, 2, 1);
        painter.drawPrimitive(QStyle::PE_FrameFocusRect, focus);
    }
}

bool WrapCheckBox::hitButton(const QPoint &pos) const
{
    return m_mayWrap ? rect().contains(pos) : QCheckBox::hitButton(pos);
}

void setFormsMayStack(QWidget *panel, bool on)
{
    // Each field under its label, the column's whole width (a choice's text whole), and back
    // to the form's own policy.
    static const char *const kOwnPolicy = "lbOwnRowWrapPolicy";
    for (QFormLayout *form : panel->findChildren<QFormLayout *>()) {
        const QVariant own = form->property(kOwnPolicy);
        if (on && !own.isValid()) {
            form->setProperty(kOwnPolicy, int(form->rowWrapPolicy()));
            form->setRowWrapPolicy(QFormLayout::WrapAllRows);
        } else if (!on && own.isValid()) {
            form->setRowWrapPolicy(QFormLayout::RowWrapPolicy(own.toInt()));
            form->setProperty(kOwnPolicy, QVariant());
        }
    }
    for (WrapRow *row : panel->findChildren<WrapRow *>())
        row->setMayStack(on);
    for (WrapCheckBox *check : panel->findChildren<WrapCheckBox *>())
        check->setMayWrap(on);
    panel->updateGeometry();
}

QRect ElidingComboBox::textField(const QStyleOptionComboBox &option) const
{
    return style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField,
                                   this);
}

QString ElidingComboBox::shownText() const
{
    QStyleOptionComboBox option;
    initStyleOption(&option);
    return fontMetrics().elidedText(option.currentText, Qt::ElideRight, textField(option).width());
}

// QComboBox's own painting, its label's text elided to the field.
void ElidingComboBox::paintEvent(QPaintEvent *)
{
    QStylePainter painter(this);
    painter.setPen(palette().color(QPalette::Text));
    QStyleOptionComboBox option;
    initStyleOption(&option);
    painter.drawComplexControl(QStyle::CC_ComboBox, option);
    if (!isEditable())
        option.currentText = shownText();
    painter.drawControl(QStyle::CE_ComboBoxLabel, option);
}

} // namespace lb
