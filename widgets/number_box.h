#pragma once
// The boxes every number a user types goes through, read alike in every locale (issue 28):
// a point or a comma is the decimal separator ("2.5" and "2,5" are both two and a half), there
// are no thousands separators, and a value is shown with the widget locale's separator.
// Text that is not one number this box can hold ("1.000,5", "2.55" in a field of one decimal,
// 400 where 360 is the most, "2.5" in a whole-number field) is never read as another number:
// it stays as typed, in red, its tooltip says why, and Enter does not take it (leaving the
// box puts the last value back, as QAbstractSpinBox does).

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QValidator>

class QLineEdit;

namespace lb {

class NumberBox : public QDoubleSpinBox
{
    Q_OBJECT
public:
    explicit NumberBox(QWidget *parent = nullptr);

    // What a typed text (prefix and suffix removed) says.
    enum class Problem {
        None,       // a number this box takes
        InProgress, // nothing wrong yet: "", "-", "0" on the way to 0.5 where 0.05 is the least
        NotANumber, // a sign inside, a letter
        Separators, // two separators ("1.000,5"), a space or other thousands separator
        Decimals,   // more digits after the separator than the box holds
        Range,      // a number outside the box's range
    };
    struct Reading
    {
        QValidator::State state = QValidator::Intermediate;
        double value = 0.0;
        Problem problem = Problem::InProgress;
        bool hopeless = false; // typing more cannot make it a number this box takes
    };
    // Reads `text` as a number with at most `decimals` digits after its one separator (a
    // point, a comma or `locale`'s decimal point; none at all for `wholeNumber`), within
    // [minimum, maximum]. Never Invalid: a key is never refused, so the text shown is the
    // text typed ("2x5" is not a number, where a refused "x" would have made it 25).
    static Reading read(QStringView text, int decimals, double minimum, double maximum,
                        const QLocale &locale, bool wholeNumber = false);

    // Why the text in the box would not be taken; empty when it would, or while typing may
    // still make it a number (an empty box, a lone sign).
    QString problem() const;
    // Takes the text typed as the value, as Enter does; false, with the box focused and the
    // reason shown, when it would not be taken. For a dialog's OK, which a shortcut may press
    // while the text is still unread (keyboard tracking is off).
    bool takeTyped();

    QValidator::State validate(QString &text, int &pos) const override;
    double valueFromText(const QString &text) const override;
    QString textFromValue(double value) const override;
    void fixup(QString &text) const override; // guesses nothing: see number_box.cpp

protected:
    void keyPressEvent(QKeyEvent *event) override;
    // Leaving the box puts the last value back (QAbstractSpinBox, without a textChanged): the
    // mark goes with the refused text.
    void focusOutEvent(QFocusEvent *event) override;

private:
    Reading readText(const QString &text) const;
    void showProblem();
    bool m_marked = false;
};

// The same for whole numbers: any separator is refused ("1.000" is a thousand to a German
// reader and one to an English one; "2.5" is neither 25 nor 2).
class IntegerBox : public QSpinBox
{
    Q_OBJECT
public:
    explicit IntegerBox(QWidget *parent = nullptr);

    QString problem() const;
    // Why the maximum is what it is, added to the problem of a number above it ("This box
    // takes 3 to 690. More would take ..."); empty: nothing added.
    void setMaximumReason(const QString &reason) { m_maximumReason = reason; }
    // Takes the text typed as the value, as Enter does; false, with the box focused and the
    // reason shown, when it would not be taken. For a dialog's OK, which a shortcut may press
    // while the text is still unread (keyboard tracking is off).
    bool takeTyped();

    QValidator::State validate(QString &text, int &pos) const override;
    int valueFromText(const QString &text) const override;
    QString textFromValue(int value) const override;
    void fixup(QString &text) const override;

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override; // as NumberBox's

private:
    NumberBox::Reading readText(const QString &text) const;
    void showProblem();
    bool m_marked = false;
    QString m_maximumReason;
};

} // namespace lb
