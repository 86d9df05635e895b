// The number boxes as a user types into them, under German and Portuguese as the default
// locale (a comma is their decimal separator; German groups thousands with a point,
// Portuguese with a space): a point and a comma both give two and a half, text with both is
// not taken as any number, the box shows the locale's separator, and every locale reads back
// what it shows.
#include "number_box.h"

#include <QApplication>
#include <QFocusEvent>
#include <QLineEdit>
#include <QTest>

#include <cmath>
#include <memory>

using namespace lb;

namespace {

// Puts `locale` as the default for the boxes made while it lives; the old default after.
class DefaultLocale
{
public:
    explicit DefaultLocale(const QString &name) { QLocale::setDefault(QLocale(name)); }
    ~DefaultLocale() { QLocale::setDefault(m_old); }

private:
    QLocale m_old;
};

// Selects what the box shows and types `text` over it, key by key, then Enter, as a user.
void type(QAbstractSpinBox *box, const QString &text)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

QString shown(QAbstractSpinBox *box)
{
    return box->findChild<QLineEdit *>()->text();
}

std::unique_ptr<NumberBox> makeBox(double lo, double hi, int decimals, double value)
{
    auto box = std::make_unique<NumberBox>();
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSingleStep(0.1);
    box->setValue(value);
    box->show();
    return box;
}

} // namespace

class TestNumberBox : public QObject
{
    Q_OBJECT
private slots:
    void typedNumbers_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("value"); // NAN: refused, the box keeps 1 and the text
        QTest::addColumn<QString>("text"); // what the box shows afterwards
        for (const char *locale : {"de_DE", "pt_PT"}) {
            const auto row = [&](const char *typed, double value, const char *text) {
                QTest::addRow("%s %s", locale, typed) << locale << typed << value << text;
            };
            row("2.5", 2.5, "2,50");
            row("2,5", 2.5, "2,50");
            row("-2.5", -2.5, "-2,50");
            row("-2,25", -2.25, "-2,25");
            row(".5", 0.5, "0,50");
            row("999.99", 999.99, "999,99");
            row("2.", 2.0, "2,00");
            row("1000", 1000.0, "1000,00");     // no thousands separator shown
            row("1.000,5", NAN, "1.000,5");     // a German thousand and a half: refused
            row("1,000.5", NAN, "1,000.5");     // an English one: refused
            row("1.000.000", NAN, "1.000.000"); // thousands separators: refused
            row("1 000", NAN, "1 000");
            row("2.555", NAN, "2.555"); // more decimals than the box holds: never rounded
            row("1001", NAN, "1001");   // beyond the range: not clamped
            row("-1000.01", NAN, "-1000.01");
            row("2x5", NAN, "2x5"); // not 25
            row("2-5", NAN, "2-5");
        }
    }
    void typedNumbers()
    {
        QFETCH(QString, locale);
        QFETCH(QString, typed);
        QFETCH(double, value);
        QFETCH(QString, text);
        const DefaultLocale scope(locale);
        const auto box = makeBox(-1000, 1000, 2, 1.0);
        QCOMPARE(shown(box.get()), QString("1,00"));
        type(box.get(), typed);
        if (std::isnan(value)) {
            QCOMPARE(box->value(), 1.0);
            QCOMPARE(shown(box.get()), text); // kept as typed, with the reason
            QVERIFY(!box->problem().isEmpty());
            QVERIFY(box->findChild<QLineEdit *>()->toolTip() == box->problem());
            // Leaving the box puts the value back.
            QFocusEvent out(QEvent::FocusOut, Qt::TabFocusReason);
            QApplication::sendEvent(box.get(), &out);
            QCOMPARE(shown(box.get()), QString("1,00"));
            QVERIFY(box->problem().isEmpty());
        } else {
            QCOMPARE(box->value(), value);
            QCOMPARE(shown(box.get()), text);
            QVERIFY(box->problem().isEmpty());
        }
    }

    // The valueChanged signal carries only numbers that were typed, once.
    void aRefusedTextChangesNothing()
    {
        const DefaultLocale scope("de_DE");
        const auto box = makeBox(-1000, 1000, 2, 1.0);
        int changes = 0;
        connect(box.get(), &QDoubleSpinBox::valueChanged, this, [&] { ++changes; });
        type(box.get(), "1.000,5");
        QCOMPARE(changes, 0);
        type(box.get(), "2.5");
        QCOMPARE(changes, 1);
        QCOMPARE(box->value(), 2.5);
    }

    // Leaving a box that holds refused text puts the last value back, and its red mark and
    // reason go with the text (they stayed, beside a value that was fine).
    void leavingPutsTheValueBackUnmarked()
    {
        const DefaultLocale scope("de_DE");
        const auto box = makeBox(-1000, 1000, 2, 2.5);
        QLineEdit *edit = box->findChild<QLineEdit *>();
        type(box.get(), "1.000,5");
        QVERIFY(!edit->toolTip().isEmpty());
        QCOMPARE(edit->palette().color(QPalette::Text), QColor(200, 0, 0));
        QFocusEvent out(QEvent::FocusOut, Qt::TabFocusReason);
        QApplication::sendEvent(box.get(), &out);
        QCOMPARE(shown(box.get()), QString("2,50"));
        QCOMPARE(box->value(), 2.5);
        QCOMPARE(edit->toolTip(), QString());
        QVERIFY(edit->palette().color(QPalette::Text) != QColor(200, 0, 0));
    }

    // A suffix, a range from 0, one decimal: the light's spot cutoff.
    void suffixAndOneDecimal_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("value");
        for (const char *locale : {"de_DE", "pt_PT"}) {
            const auto row = [&](const char *typed, double value) {
                QTest::addRow("%s %s", locale, typed) << locale << typed << value;
            };
            row("45.5", 45.5);
            row("45,5", 45.5);
            row("45", 45.0);
            row("2.55", NAN); // not 2.5 (a dropped key) nor 2.6 (rounded)
            row("200", NAN);  // not 20 (a dropped key) nor 180 (clamped)
            row("-2", NAN);   // not 2 (a dropped sign)
            row("1.000", NAN);
        }
    }
    void suffixAndOneDecimal()
    {
        QFETCH(QString, locale);
        QFETCH(QString, typed);
        QFETCH(double, value);
        const DefaultLocale scope(locale);
        const auto box = makeBox(0, 180, 1, 90.0);
        box->setSuffix(QString::fromUtf8("°"));
        QCOMPARE(shown(box.get()), QString::fromUtf8("90,0°"));
        type(box.get(), typed);
        if (std::isnan(value)) {
            QCOMPARE(box->value(), 90.0);
            QCOMPARE(shown(box.get()), typed + QString::fromUtf8("°"));
            QVERIFY(!box->problem().isEmpty());
        } else {
            QCOMPARE(box->value(), value);
            QCOMPARE(shown(box.get()), QLocale().toString(value, 'f', 1) + QString::fromUtf8("°"));
        }
    }

    // The arrow keys step from the number typed, read as the user meant it.
    void stepsFromTheTypedNumber()
    {
        const DefaultLocale scope("de_DE");
        const auto box = makeBox(-1000, 1000, 2, 1.0);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box.get(), "2.5");
        QTest::keyClick(box.get(), Qt::Key_Up); // without Enter first
        QCOMPARE(box->value(), 2.6);
        QCOMPARE(shown(box.get()), QString("2,60"));
        QTest::keyClick(box.get(), Qt::Key_Down);
        QTest::keyClick(box.get(), Qt::Key_Down);
        QCOMPARE(box->value(), 2.4);
    }

    void wholeNumbers_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<int>("value"); // -1: refused, the box keeps 512
        for (const char *locale : {"de_DE", "pt_PT"}) {
            const auto row = [&](const char *typed, int value) {
                QTest::addRow("%s %s", locale, typed) << locale << typed << value;
            };
            row("2000", 2000);
            row("64", 64);
            row("1.000", -1); // a thousand in German, one in English: neither
            row("1,000", -1);
            row("2.5", -1); // not 25, not 2
            row("2 000", -1);
            row("63", -1); // below the range
            row("5000", -1);
        }
    }
    void wholeNumbers()
    {
        QFETCH(QString, locale);
        QFETCH(QString, typed);
        QFETCH(int, value);
        const DefaultLocale scope(locale);
        IntegerBox box;
        box.setRange(64, 4096);
        box.setSuffix(" MB");
        box.setValue(512);
        box.show();
        type(&box, typed);
        if (value < 0) {
            QCOMPARE(box.value(), 512);
            QCOMPARE(shown(&box), typed + " MB");
            QVERIFY(!box.problem().isEmpty());
        } else {
            QCOMPARE(box.value(), value);
            QCOMPARE(shown(&box), QString::number(value) + " MB"); // no "2.000 MB"
        }
    }

    // Whatever the locale, the box reads back the text it shows: its digits, its signs,
    // its decimal separator; no thousands separator is shown.
    void everyLocaleReadsWhatItShows_data()
    {
        QTest::addColumn<QString>("locale");
        for (const char *name : {"C", "en_US", "de_DE", "pt_PT", "pt_BR", "fr_FR", "de_CH", "it_IT",
                                 "ru_RU", "ar_EG", "fa_IR", "hi_IN", "sv_SE"})
            QTest::newRow(name) << name;
    }
    void everyLocaleReadsWhatItShows()
    {
        QFETCH(QString, locale);
        const DefaultLocale scope(locale);
        const auto box = makeBox(-100000, 100000, 3, 0.0);
        for (double v : {-12345.678, -0.5, 0.0, 1.8, 99999.999}) {
            box->setValue(v);
            QString text = shown(box.get());
            QVERIFY2(!text.contains(QLocale().groupSeparator()), qPrintable(text));
            int pos = 0;
            QCOMPARE(box->validate(text, pos), QValidator::Acceptable);
            QCOMPARE(box->valueFromText(text), v);
        }
        IntegerBox whole;
        whole.setRange(-100000, 100000);
        whole.setValue(-12345);
        QString text = shown(&whole);
        int pos = 0;
        QCOMPARE(whole.validate(text, pos), QValidator::Acceptable);
        QCOMPARE(whole.valueFromText(text), -12345);
    }

    // -0.001 in a box of two decimals is 0,00, not -0,00.
    void noNegativeZero()
    {
        const DefaultLocale scope("de_DE");
        const auto box = makeBox(-10, 10, 2, -0.001);
        QCOMPARE(shown(box.get()), QString("0,00"));
    }
};

QTEST_MAIN(TestNumberBox)
#include "test_number_box.moc"
