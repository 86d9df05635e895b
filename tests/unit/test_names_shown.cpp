// Names shown safely (issue 29): a submission's file name, a scene's or an exercise's title
// reach the terminal, the window and the CSV with their controls escaped, and CSV cells stay
// data. Bad inputs tried: a newline followed by a fake result line, CR, a tab, ESC colour
// and title sequences, other C0 and C1 controls, DEL, the Unicode line separator and a
// right-to-left override, backslashes that would fake an escape; CSV cells led by = + - @,
// a tab and a CR, and holding commas, quotes and line breaks.

#include "csv_cell.h"
#include "message_text.h"

#include <QTest>

using namespace lb;

namespace {

// The cells of one CSV record as RFC 4180 reads them (quoted fields, "" inside quotes).
QStringList readRecord(const QString &line)
{
    QStringList cells{QString()};
    bool quoted = false;
    for (int i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            cells.back() += '"', ++i;
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            cells << QString();
        else
            cells.back() += c;
    }
    return cells;
}

} // namespace

class TestNamesShown : public QObject
{
    Q_OBJECT
private slots:
    void controlsAreEscaped_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("shown");
        QTest::newRow("plain") << "alice"
                               << "alice";
        QTest::newRow("letters beyond ASCII")
            << QString::fromUtf8("Jürgen_日本") << QString::fromUtf8("Jürgen_日本");
        QTest::newRow("fake result line") << "x\nalice: passed, 20/20 cases passed"
                                          << "x\\nalice: passed, 20/20 cases passed";
        QTest::newRow("CR over the line") << "bob\rcarol: passed"
                                          << "bob\\rcarol: passed";
        QTest::newRow("tab") << "a\tb"
                             << "a\\tb";
        QTest::newRow("ESC colour") << "\x1b[31mred\x1b[0m"
                                    << "\\x1b[31mred\\x1b[0m";
        QTest::newRow("ESC title") << "\x1b]0;pwned\x07"
                                   << "\\x1b]0;pwned\\x07";
        QTest::newRow("NUL and DEL") << QString(QChar(0)) + "a\x7f"
                                     << "\\x00a\\x7f";
        QTest::newRow("C1 NEL and CSI") << QString(QChar(0x85)) + QChar(0x9b) + "1m"
                                        << "\\x85\\x9b1m";
        QTest::newRow("line separator") << "a" + QString(QChar(0x2028)) + "b"
                                        << "a\\u2028b";
        QTest::newRow("right-to-left override") << "alice" + QString(QChar(0x202e)) + "gnp.exe"
                                                << "alice\\u202egnp.exe";
        QTest::newRow("backslash n typed") << "a\\nb"
                                           << "a\\\\nb";
    }
    void controlsAreEscaped()
    {
        QFETCH(QString, name);
        QFETCH(QString, shown);
        const QString out = escapedName(name);
        QCOMPARE(out, shown);
        for (const QChar c : out)
            QVERIFY2(c.unicode() >= 0x20 && c.unicode() != 0x7f &&
                         !(c.unicode() >= 0x80 && c.unicode() <= 0x9f) && c.unicode() != 0x2028 &&
                         c.unicode() != 0x202e,
                     qPrintable(QString::number(c.unicode(), 16)));
    }

    // The text around a name escaped where it was written: controls escaped, the name's
    // escapes not escaped again.
    void textAroundNamesKeepsItsBackslashes()
    {
        const QString diagnostic = escapedName("x\ny") + ".frag:26: error\tthere\x1b[2J";
        QCOMPARE(escapedControls(diagnostic), QString("x\\ny.frag:26: error\\tthere\\x1b[2J"));
    }

    void csvCellsStayData_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("cell");
        QTest::newRow("plain") << "alice"
                               << "alice";
        QTest::newRow("empty") << ""
                               << "";
        QTest::newRow("formula =") << "=1+1"
                                   << "\"'=1+1\"";
        QTest::newRow("formula +") << "+1"
                                   << "\"'+1\"";
        QTest::newRow("formula -") << "-1"
                                   << "\"'-1\"";
        QTest::newRow("formula @") << "@SUM(A1)"
                                   << "\"'@SUM(A1)\"";
        QTest::newRow("leading tab") << "\t=1+1"
                                     << "\"'\t=1+1\"";
        QTest::newRow("leading CR") << "\r=1+1"
                                    << "\"'\r=1+1\"";
        QTest::newRow("comma") << "a,b"
                               << "\"a,b\"";
        QTest::newRow("quote") << "say \"hi\""
                               << "\"say \"\"hi\"\"\"";
        QTest::newRow("CR inside") << "a\rb"
                                   << "\"a\rb\"";
        QTest::newRow("LF inside") << "a\nb"
                                   << "\"a\nb\"";
        QTest::newRow("escaped name")
            << escapedName("x\n=cmd|' /C calc'!A0") << "x\\n=cmd|' /C calc'!A0";
    }
    void csvCellsStayData()
    {
        QFETCH(QString, text);
        QFETCH(QString, cell);
        QCOMPARE(csvCell(text), cell);
        // Read back as RFC 4180 has it: one cell, the text (led by a quote mark if it was a
        // formula).
        if (!text.contains('\n') && !text.contains('\r')) {
            const QStringList back = readRecord(csvCell(text) + ",next");
            QCOMPARE(back.size(), 2);
            QVERIFY(back[0] == text || back[0] == "'" + text);
        }
    }
};

QTEST_MAIN(TestNamesShown)
#include "test_names_shown.moc"
