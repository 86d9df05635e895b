// The man page and the bash completion against the options the parser knows: every visible
// option in both, each fixed value one the parser takes, roff escaped (a '.' or '\'' at a
// line's start, backslashes, hyphens, past ASCII), `man --warnings` silent, and the built
// completion driven in bash (`--lan<TAB>`, `--language <TAB>`, files by their endings).
// The files under test are the build's own (LB_DOCS_DIR), checked to be what the code writes.
#include "cli_docs.h"
#include "command_line.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace lb;

namespace {

QString builtFile(const QString &name)
{
    QFile file(QDir(LB_DOCS_DIR).filePath(name));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

QString dashed(const QString &name)
{
    return (name.size() == 1 ? "-" : "--") + name;
}

} // namespace

class TestCliDocs : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;

    // What the completion offers for `words` (the command line up to the cursor, the last
    // word the one completed), run in `m_dir`: one entry per line.
    QStringList complete(const QStringList &words)
    {
        QProcess bash;
        bash.setWorkingDirectory(m_dir.path());
        QStringList quoted;
        for (const QString &w : words)
            quoted << "'" + QString(w).replace("'", "'\\''") + "'";
        bash.start("bash", {"--norc", "--noprofile", "-c",
                            "source \"$0\" && COMP_WORDS=(" + quoted.join(' ') +
                                ") && COMP_CWORD=$((${#COMP_WORDS[@]} - 1)) && _lightbench && "
                                "printf '%s\\n' \"${COMPREPLY[@]}\"",
                            QDir(LB_DOCS_DIR).filePath("lightbench")});
        if (!bash.waitForFinished(10000))
            bash.kill();
        QStringList offered = QString::fromUtf8(bash.readAllStandardOutput()).split('\n');
        offered.removeAll(QString());
        offered.sort();
        return offered;
    }

private slots:
    void theBuiltFilesAreTheCodes()
    {
        // What lightbench_docs wrote is what the code writes now: built with the options.
        QCOMPARE(builtFile("lightbench.1"), manPage());
        QCOMPARE(builtFile("lightbench"), bashCompletion());
    }

    // --help, the man page and the completion list the same options: the parser's.
    void everyVisibleOptionIsDocumented()
    {
        const std::vector<OptionInfo> options = visibleOptions();
        QVERIFY(options.size() > 50);
        const QString page = manPage(), completion = bashCompletion();
        const CommandLineResult help = parseCommandLine({"lightbench", "--help"});
        QSet<QString> known;
        for (const OptionInfo &o : options) {
            for (const QString &name : o.names) {
                known << dashed(name);
                QVERIFY2(page.contains("\\fB" + roffEscaped(dashed(name)) + "\\fR"),
                         qPrintable(name));
                QVERIFY2(completion.contains(QRegularExpression(
                             "compgen -W '([^']* )?" + QRegularExpression::escape(dashed(name)) +
                             "( |')")),
                         qPrintable(name));
            }
            if (!o.valueName.isEmpty()) // its value has a branch (maybe one offering nothing)
                QVERIFY2(completion.contains(QRegularExpression(
                             "[ |]" + QRegularExpression::escape("--" + o.longName()) + "[|)]")),
                         qPrintable(o.longName()));
            QVERIFY2(page.contains(roffEscaped(o.description)), qPrintable(o.longName()));
        }
        // And nothing the parser does not list: the hidden --grade-one stays out.
        for (const QRegularExpressionMatch &m :
             QRegularExpression("(?<![\\w-])--?[a-z][a-z0-9-]*").globalMatch(help.message))
            if (help.message.mid(m.capturedStart() - 2, 2) == "  " ||
                help.message.mid(m.capturedStart() - 2, 2) == ", ")
                QVERIFY2(known.contains(m.captured()), qPrintable(m.captured()));
        QVERIFY(!page.contains("grade\\-one") && !completion.contains("grade-one"));
        QVERIFY(page.contains(QString("\"lightbench %1\"").arg(LB_PROJECT_VERSION)));
    }

    // A fixed value the docs offer is one the parser takes, and only those: the lists are the
    // parser's own (scene.h's names, --language's, on|off).
    void fixedValuesAreThoseTheParserTakes()
    {
        int lists = 0;
        for (const OptionInfo &o : visibleOptions()) {
            if (o.words.isEmpty())
                continue;
            ++lists;
            // An option that goes with others is tried in their company.
            const QStringList with =
                o.longName() == "report-format"
                    ? QStringList{"--grade", "s.vert", "--exercise", "e.json", "--report", "-"}
                : o.longName() == "plot" ? QStringList{"--plot-data", "plot.csv"}
                                         : QStringList{};
            for (const QString &word : o.words) {
                const CommandLineResult r =
                    parseCommandLine(QStringList{"lightbench", "--" + o.longName(), word} + with);
                QVERIFY2(r.commandLine, qPrintable(o.longName() + " " + word + ": " + r.message));
            }
            const CommandLineResult bad = parseCommandLine(
                QStringList{"lightbench", "--" + o.longName(), "not-a-" + o.words[0]} + with);
            // --object takes a mesh file's name as well.
            QCOMPARE(bool(bad.commandLine), o.files);
        }
        QVERIFY(lists >= 15);
    }

    // Text that roff would take as a request or an escape comes out as printed text.
    void roffIsEscaped_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("escaped");
        QTest::newRow("request at the start") << ".TH evil"
                                              << "\\&.TH evil";
        QTest::newRow("request after a line break") << "a\n.SH x"
                                                    << "a\n\\&.SH x";
        QTest::newRow("no-break control") << "'br"
                                          << "\\&'br";
        QTest::newRow("a point inside") << "a.b"
                                        << "a.b";
        QTest::newRow("backslash escape") << "a\\fBb"
                                          << "a\\efBb";
        QTest::newRow("hyphens") << "--scene x-y"
                                 << "\\-\\-scene x\\-y";
        QTest::newRow("past ASCII") << "Português"
                                    << "Portugu\\[u00EA]s";
        QTest::newRow("past the BMP") << QString::fromUtf8("a\xF0\x9F\x98\x80") << "a\\[u1F600]";
    }
    void roffIsEscaped()
    {
        QFETCH(QString, text);
        QFETCH(QString, escaped);
        QCOMPARE(roffEscaped(text), escaped);
    }

    // Every line that starts with a control character is a request the page means.
    void onlyOurRequestsStartALine()
    {
        const QSet<QString> requests{".\\\"", ".TH", ".SH", ".TP", ".PP",
                                     ".br",   ".nf", ".fi", ".RS", ".RE"};
        for (const QString &line : manPage().split('\n'))
            if (line.startsWith('.') || line.startsWith('\''))
                QVERIFY2(requests.contains(line.section(' ', 0, 0)), qPrintable(line));
    }

    void manFindsNothingToWarnAbout()
    {
        if (QStandardPaths::findExecutable("man").isEmpty())
            QSKIP("man is not installed");
        for (const char *width : {"80", "60"}) {
            QProcess man;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("MANWIDTH", width);
            man.setProcessEnvironment(env);
            man.start("man", {"--warnings", "-l", QDir(LB_DOCS_DIR).filePath("lightbench.1")});
            QVERIFY(man.waitForFinished(30000));
            QCOMPARE(man.exitCode(), 0);
            QCOMPARE(QString::fromUtf8(man.readAllStandardError()), QString());
            QVERIFY(man.readAllStandardOutput().contains("EXIT STATUS"));
        }
    }

    void completionOffersOptionsValuesAndFiles()
    {
        if (QStandardPaths::findExecutable("bash").isEmpty())
            QSKIP("bash is not installed");
        for (const char *name :
             {"a.lbscene", "b.json", "c.lblesson", "d.png", "e.txt", "f g.LBSCENE"}) {
            QFile f(m_dir.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
        }
        QVERIFY(QDir(m_dir.path()).mkdir("folder"));

        QCOMPARE(complete({"lightbench", "--lan"}), QStringList{"--language"});
        QStringList languages = commandLineLanguages();
        languages.sort();
        QCOMPARE(complete({"lightbench", "--language", ""}), languages);
        QCOMPARE(complete({"lightbench", "--language", "p"}), QStringList{"pt"});
        for (const OptionInfo &o : visibleOptions()) {
            if (o.words.isEmpty() || o.files)
                continue;
            QStringList words = o.words;
            words.sort();
            QCOMPARE(complete({"lightbench", "--" + o.longName(), ""}), words);
        }
        // Files by their endings (in any case), folders to look into; a name with a space.
        const QStringList scenes{"a.lbscene", "b.json", "f g.LBSCENE", "folder"};
        QCOMPARE(complete({"lightbench", "--scene", ""}), scenes);
        QCOMPARE(complete({"lightbench", "--lesson", ""}),
                 QStringList({"b.json", "c.lblesson", "folder"}));
        QCOMPARE(complete({"lightbench", "--render", ""}), QStringList({"d.png", "folder"}));
        QCOMPARE(complete({"lightbench", "--sheets", ""}), QStringList{"folder"});
        QCOMPARE(complete({"lightbench", "--size", ""}), QStringList()); // a value to type
        QCOMPARE(complete({"lightbench", ""}),
                 QStringList({"a.lbscene", "b.json", "c.lblesson", "f g.LBSCENE", "folder"}));
        // After --grade, submissions: any file or folder.
        QCOMPARE(complete({"lightbench", "--grade", "--exercise", "b.json", ""}).size(), 7);
        QStringList object = complete({"lightbench", "--object", ""});
        for (const QString &shape : shapeWords())
            QVERIFY2(object.contains(shape), qPrintable(object.join(' ')));
        QVERIFY(object.contains("e.txt")); // a mesh file of any format
    }

private:
    static QStringList shapeWords()
    {
        for (const OptionInfo &o : visibleOptions())
            if (o.longName() == "shape")
                return o.words;
        return {};
    }
};

QTEST_GUILESS_MAIN(TestCliDocs)
#include "test_cli_docs.moc"
