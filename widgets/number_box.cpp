#include "number_box.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <QToolTip>

#include <cmath>
#include <initializer_list>

namespace lb {

namespace {

// Marks that only set the direction of bidirectional text (QLocale puts them around the sign
// in Arabic locales): they are not typed, and mean nothing in a number.
bool isDirectionMark(QChar c)
{
    return c == QChar(0x200E) || c == QChar(0x200F) || c == QChar(0x061C);
}

QString withoutDirectionMarks(QStringView text)
{
    QString s;
    s.reserve(text.size());
    for (QChar c : text)
        if (!isDirectionMark(c))
            s += c;
    return s;
}

// The length of the first of `signs` that `text` starts with, 0 when none.
qsizetype signAtStart(QStringView text, std::initializer_list<QString> signs)
{
    for (const QString &sign : signs)
        if (!sign.isEmpty() && text.startsWith(sign))
            return sign.size();
    return 0;
}

// Thousands separators of one locale or another, and spaces: never part of a number here.
bool isOtherSeparator(QChar c, const QLocale &locale)
{
    return c.isSpace() || c == '\'' || c == QChar(0x2019) || c == QChar(0x066C) ||
           QString(c) == locale.groupSeparator();
}

// Text with the box's prefix and suffix taken off, where they are, and trimmed (as
// QAbstractSpinBox does before it reads a number).
QStringView stripped(QStringView text, const QString &prefix, const QString &suffix)
{
    if (!prefix.isEmpty() && text.startsWith(prefix))
        text = text.mid(prefix.size());
    if (!suffix.isEmpty() && text.endsWith(suffix))
        text.chop(suffix.size());
    return text.trimmed();
}

QString describe(const NumberBox::Reading &r, int decimals, bool wholeNumber, const QString &lowest,
                 const QString &highest)
{
    using P = NumberBox::Problem;
    switch (r.problem) {
    case P::None:
    case P::InProgress:
        return {};
    case P::NotANumber:
        return NumberBox::tr("Not a number: digits, a sign in front and one decimal separator.");
    case P::Separators:
        return wholeNumber ? NumberBox::tr("A whole number, typed without separators.")
                           : NumberBox::tr("One decimal separator, a point or a comma (2.5 or "
                                           "2,5), and no thousands separators.");
    case P::Decimals:
        // A count: Qt's plural forms pick the word ("%n decimal(s)"), not this code.
        return decimals == 0 ? NumberBox::tr("This box takes whole numbers.")
                             //: %n the digits allowed after the decimal separator
                             : NumberBox::tr("This box takes %n decimal(s).", nullptr, decimals);
    case P::Range:
        //: %1 the lowest number the box takes, %2 the highest (with their units)
        return NumberBox::tr("This box takes %1 to %2.").arg(lowest, highest);
    }
    return {};
}

// Shows a text that cannot become a number the box takes in red, with the reason as the
// tooltip of the text (the box's own tooltip, which panels rewrite, stays).
void mark(QLineEdit *edit, bool &marked, const QString &problem)
{
    const bool on = !problem.isEmpty();
    if (on) {
        QPalette p = edit->palette();
        p.setColor(QPalette::Text, QColor(200, 0, 0));
        edit->setPalette(p);
    } else if (marked) {
        edit->setPalette(QPalette()); // back to the box's own
    }
    if (on || marked)
        edit->setToolTip(problem);
    marked = on;
}

// A text that would not be taken is kept, marked, and the reason shown under the box, instead
// of the last value put back without a word; false then. Otherwise the text is read.
bool take(QAbstractSpinBox *box, QLineEdit *edit, bool &marked, const QString &problem)
{
    if (problem.isEmpty()) {
        box->interpretText();
        return true;
    }
    box->setFocus();
    mark(edit, marked, problem);
    QToolTip::showText(box->mapToGlobal(box->rect().bottomLeft()), problem, box);
    return false;
}

bool isEnter(const QKeyEvent *event)
{
    return event->key() == Qt::Key_Enter || event->key() == Qt::Key_Return;
}

} // namespace

NumberBox::Reading NumberBox::read(QStringView text, int decimals, double minimum, double maximum,
                                   const QLocale &locale, bool wholeNumber)
{
    Reading r;
    const QString s = withoutDirectionMarks(text);
    QStringView t = QStringView(s).trimmed();
    const QString negative = withoutDirectionMarks(locale.negativeSign());
    const QString positive = withoutDirectionMarks(locale.positiveSign());
    const QString decimalPoint = locale.decimalPoint();
    bool isNegative = false;
    if (const qsizetype n =
            signAtStart(t, {QStringLiteral("-"), QString(QChar(0x2212)), negative})) {
        isNegative = true;
        t = t.mid(n);
    } else if (const qsizetype p = signAtStart(t, {QStringLiteral("+"), positive})) {
        t = t.mid(p);
    }

    QString integer, fraction;
    int separators = 0;
    bool otherSeparator = false, notANumber = false;
    for (QChar c : t) {
        if (c.isDigit()) // any script's digits: QLocale writes Arabic-Indic ones in Arabic
            (separators > 0 ? fraction : integer) += QChar('0' + c.digitValue());
        else if (c == '.' || c == ',' || QString(c) == decimalPoint)
            ++separators;
        else if (isOtherSeparator(c, locale))
            otherSeparator = true;
        else // a sign inside, a letter: kept as typed (a refused key would make "2x5" 25)
            notANumber = true;
    }
    r.hopeless = true; // from here on unless said otherwise
    if (notANumber) {
        r.problem = Problem::NotANumber;
        return r;
    }
    if (separators > 1 || otherSeparator || (wholeNumber && separators > 0)) {
        r.problem = Problem::Separators;
        return r;
    }
    if (integer.isEmpty() && fraction.isEmpty()) { // "", "-", "." on the way to a number
        r.problem = Problem::InProgress;
        r.hopeless = false;
        return r;
    }
    if (fraction.size() > decimals) { // never rounded to another number
        r.problem = Problem::Decimals;
        return r;
    }
    bool ok = false;
    const QString c = (isNegative ? QStringLiteral("-") : QString()) +
                      (integer.isEmpty() ? QStringLiteral("0") : integer) + '.' + fraction;
    double value = c.toDouble(&ok); // the C locale
    if (!ok || !std::isfinite(value))
        value = isNegative ? -HUGE_VAL : HUGE_VAL;
    r.value = value == 0.0 ? 0.0 : value; // "-0" is 0
    if (r.value < minimum || r.value > maximum) {
        r.problem = Problem::Range;
        // More digits only take a number further from 0: 0 on the way to 0.5 where 0.05 is
        // the least is not hopeless yet; 400 where 360 is the most, or -2 where 0 is, are.
        r.hopeless = (r.value > maximum && r.value > 0) || (r.value < minimum && r.value < 0);
        return r;
    }
    r.state = QValidator::Acceptable;
    r.problem = Problem::None;
    r.hopeless = false;
    return r;
}

// NumberBox

NumberBox::NumberBox(QWidget *parent) : QDoubleSpinBox(parent)
{
    // Typing "1.25" edits once, not four times; and every start of a text is a number of its
    // own: "1.000,5" would set 1 on its way to being refused.
    setKeyboardTracking(false);
    connect(lineEdit(), &QLineEdit::textChanged, this, &NumberBox::showProblem);
}

NumberBox::Reading NumberBox::readText(const QString &text) const
{
    if (!specialValueText().isEmpty() && text == specialValueText())
        return {QValidator::Acceptable, minimum(), Problem::None, false};
    return read(stripped(text, prefix(), suffix()), decimals(), minimum(), maximum(), locale());
}

QString NumberBox::problem() const
{
    return describe(readText(lineEdit()->text()), decimals(), false,
                    prefix() + textFromValue(minimum()) + suffix(),
                    prefix() + textFromValue(maximum()) + suffix());
}

QValidator::State NumberBox::validate(QString &text, int &) const
{
    return readText(text).state;
}

double NumberBox::valueFromText(const QString &text) const
{
    const Reading r = readText(text);
    return r.state == QValidator::Acceptable ? r.value : value();
}

QString NumberBox::textFromValue(double value) const
{
    QLocale l = locale();
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(value == 0.0 ? 0.0 : value, 'f', decimals()); // no "-0.00"
}

// QDoubleSpinBox's own fixup takes the locale's group separators out: in German "1.000,5"
// would become "1000,5" and be read as 1000.5. A text that is not a number stays as typed.
void NumberBox::fixup(QString &) const {}

bool NumberBox::takeTyped()
{
    return take(this, lineEdit(), m_marked, problem());
}

void NumberBox::keyPressEvent(QKeyEvent *event)
{
    if (isEnter(event) && !takeTyped())
        event->accept(); // nor does a dialog's default button take the old value
    else
        QDoubleSpinBox::keyPressEvent(event);
}

void NumberBox::focusOutEvent(QFocusEvent *event)
{
    QDoubleSpinBox::focusOutEvent(event);
    showProblem();
}

void NumberBox::showProblem()
{
    const Reading r = readText(lineEdit()->text());
    mark(lineEdit(), m_marked, r.hopeless ? problem() : QString());
}

// IntegerBox

IntegerBox::IntegerBox(QWidget *parent) : QSpinBox(parent)
{
    setKeyboardTracking(false); // as NumberBox
    connect(lineEdit(), &QLineEdit::textChanged, this, &IntegerBox::showProblem);
}

NumberBox::Reading IntegerBox::readText(const QString &text) const
{
    if (!specialValueText().isEmpty() && text == specialValueText())
        return {QValidator::Acceptable, double(minimum()), NumberBox::Problem::None, false};
    return NumberBox::read(stripped(text, prefix(), suffix()), 0, minimum(), maximum(), locale(),
                           true);
}

QString IntegerBox::problem() const
{
    const NumberBox::Reading r = readText(lineEdit()->text());
    const QString problem = describe(r, 0, true, prefix() + textFromValue(minimum()) + suffix(),
                                     prefix() + textFromValue(maximum()) + suffix());
    if (r.problem == NumberBox::Problem::Range && r.value > maximum() && !m_maximumReason.isEmpty())
        return problem + " " + m_maximumReason;
    return problem;
}

QValidator::State IntegerBox::validate(QString &text, int &) const
{
    return readText(text).state;
}

int IntegerBox::valueFromText(const QString &text) const
{
    const NumberBox::Reading r = readText(text);
    return r.state == QValidator::Acceptable ? int(std::lround(r.value)) : value();
}

QString IntegerBox::textFromValue(int value) const
{
    QLocale l = locale();
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(value);
}

// QSpinBox's fixup, too, takes group separators out ("1.000" would be a thousand in German).
void IntegerBox::fixup(QString &) const {}

bool IntegerBox::takeTyped()
{
    return take(this, lineEdit(), m_marked, problem());
}

void IntegerBox::keyPressEvent(QKeyEvent *event)
{
    if (isEnter(event) && !takeTyped())
        event->accept();
    else
        QSpinBox::keyPressEvent(event);
}

void IntegerBox::focusOutEvent(QFocusEvent *event)
{
    QSpinBox::focusOutEvent(event);
    showProblem();
}

void IntegerBox::showProblem()
{
    const NumberBox::Reading r = readText(lineEdit()->text());
    mark(lineEdit(), m_marked, r.hopeless ? problem() : QString());
}

} // namespace lb
