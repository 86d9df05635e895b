// Submission names that try to fool the teacher's terminal or spreadsheet (issue 29): --grade
// prints every line with the name's controls escaped and writes them escaped in the CSV.
// Bad inputs tried (as file names in a temporary folder): a newline followed by a fake
// "alice: passed, 20/20 ..." line (its slashes U+2215, as a file name cannot hold '/'), an ANSI
// colour sequence, a tab, and a name starting with
// "=" (a spreadsheet formula).

#include "csv_cell.h"
#include "message_text.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;

namespace {

const QString kData = QStringLiteral(LB_TEST_DATA "/grading");
const QString kExercise = QStringLiteral(LB_EXAMPLES_DIR "/exercise_lighting.json");

// A file name cannot hold '/': U+2215 DIVISION SLASH looks the same on a terminal.
const QString kFakeLine = QString::fromUtf8("alice: passed, 20\u221520 cases passed, largest "
                                            "difference 1\u2215255, 100.0% of pixels within "
                                            "tolerance");

bool copyPair(const QString &from, const QString &to)
{
    return QFile::copy(from + ".vert", to + ".vert") && QFile::copy(from + ".frag", to + ".frag");
}

} // namespace

class TestGradeNames : public QObject
{
    Q_OBJECT
private slots:
    void namesAreShownEscaped()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QDir d(dir.path());
        // One graded (the correct program), three that do not compile: both kinds of line.
        const QStringList names{"mallory\n" + kFakeLine, "\x1b[32mgreen\x1b[0m", "tab\there",
                                "=HYPERLINK(\"x\")"};
        QVERIFY(copyPair(kData + "/correct/lighting", d.filePath(names[1])));
        for (const QString &name : {names[0], names[2], names[3]})
            QVERIFY(copyPair(kData + "/syntax", d.filePath(name)));
        QStringList args{"--grade"};
        for (const QString &name : names)
            args << d.filePath(name + ".vert") << d.filePath(name + ".frag");
        const QString report = d.filePath("grades.csv");
        args << "--exercise" << kExercise << "--report" << report;
        QProcess p;
        p.start(LIGHTBENCH_EXE, args);
        QVERIFY(p.waitForFinished(300000));
        const QByteArray out = p.readAllStandardOutput();
        qInfo().noquote() << out;
        QCOMPARE(p.exitCode(), 0);

        // The terminal: one line a submission, each starting with its name escaped; no control
        // byte but the line ends, so no fake line, colour or tab.
        const QList<QByteArray> lines = out.trimmed().split('\n');
        QCOMPARE(lines.size(), names.size());
        for (const char c : out)
            QVERIFY2(c == '\n' || (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f),
                     qPrintable(QString::number(int(c))));
        for (const QByteArray &line : lines)
            QVERIFY(!line.startsWith("alice:"));
        // The order the batch prints: the names sorted as given on the command line.
        for (int i = 0; i < names.size(); ++i)
            QVERIFY2(lines[i].startsWith((escapedName(names[i]) + ": ").toUtf8()),
                     lines[i].constData());
        QVERIFY(lines[0].startsWith("mallory\\nalice: passed, 20") &&
                lines[0].contains(": does not compile: mallory\\nalice: passed"));
        QVERIFY(lines[1].startsWith("\\x1b[32mgreen\\x1b[0m: passed, "));
        QVERIFY(lines[2].startsWith("tab\\there: does not compile: tab\\there.frag:"));

        // The CSV: the same escaped names, each row one record of 7 cells, the formula quoted.
        QFile f(report);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray csv = f.readAll();
        QVERIFY(!csv.contains('\t') && !csv.contains('\x1b') && !csv.contains('\r'));
        const QList<QByteArray> rows = csv.trimmed().split('\n');
        QCOMPARE(rows.size(), names.size() + 1);
        for (int i = 0; i < names.size(); ++i)
            QVERIFY2(rows[i + 1].startsWith((csvCell(escapedName(names[i])) + ",").toUtf8()),
                     rows[i + 1].constData());
        QVERIFY(rows[4].startsWith("\"'=HYPERLINK(\"\"x\"\")\","));
    }
};

QTEST_MAIN(TestGradeNames)
#include "test_grade_names.moc"
