// The window's words are ones lupdate can find (issue 31): Qt Linguist's lupdate reads the
// sources and collects every tr() into the .ts files translators work on. A tr() it cannot
// read (a variable, a class it cannot resolve) is a string no translation reaches. Runs
// lupdate over app/, widgets/ and render/ (as update_translations does) and checks app/'s
// part; test_translations checks the .ts files against the same sources. Bad inputs this catches:
// tr() of a variable without QT_TR_NOOP, a definition whose return type is another class's
// (QMessageBox::StandardButton f(): lupdate took the file's tr() calls for QMessageBox's and
// warned), QObject::tr() in a free function (the catch-all context "QObject"), and strings of the
// window left out of tr().

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace {

struct Message
{
    QString context, source, disambiguation;
    QStringList files; // where it is, relative to the source tree
};

QList<Message> readTs(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<Message> messages;
    QString context;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.name() == QLatin1String("message"))
            messages.push_back({context, {}, {}, {}});
        else if (xml.name() == QLatin1String("source") && !messages.isEmpty())
            messages.back().source = xml.readElementText();
        else if (xml.name() == QLatin1String("comment") && !messages.isEmpty())
            messages.back().disambiguation = xml.readElementText();
        else if (xml.name() == QLatin1String("location") && !messages.isEmpty())
            messages.back().files << QDir::cleanPath(xml.attributes().value("filename").toString());
    }
    return messages;
}

} // namespace

class TestTranslatableApp : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_output;       // what lupdate said
    QList<Message> m_found; // the .ts it wrote

private slots:
    void initTestCase()
    {
        QProcess run;
        run.setWorkingDirectory(LB_SOURCE_DIR);
        run.setProcessChannelMode(QProcess::MergedChannels);
        // Relative locations, so that the .ts names app/... whatever the checkout's path.
        const QString ts = m_dir.filePath("check_de.ts");
        run.start(LB_LUPDATE, {"app", "widgets", "render", "-locations", "relative", "-ts", ts});
        QVERIFY(run.waitForFinished(60000));
        QCOMPARE(run.exitCode(), 0);
        m_output = QString::fromLocal8Bit(run.readAll());
        m_found = readTs(ts);
        // Relative to the .ts: back to the source tree's own paths.
        for (Message &m : m_found)
            for (QString &f : m.files)
                f = QDir(LB_SOURCE_DIR).relativeFilePath(QDir(m_dir.path()).absoluteFilePath(f));
        QVERIFY2(m_found.size() > 300, qPrintable(m_output));
    }

    // No line of lupdate's output is a warning about a file of app/.
    void noWarningAboutTheWindowsFiles()
    {
        QStringList warnings;
        for (const QString &line : m_output.split('\n'))
            if (line.contains("/app/") || line.startsWith("app/"))
                warnings << line;
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join('\n')));
    }

    // Every string of app/ is in a context named for its class or its file's job (or Qt's
    // own, for the words Qt asks for), none in the catch-all "QObject" (QObject::tr in a free
    // function), where one translation would have to serve unrelated places.
    void noStringInTheCatchAllContext()
    {
        QStringList inQObject;
        for (const Message &m : m_found)
            for (const QString &f : m.files)
                if (f.startsWith("app/") && (m.context == "QObject" || m.context.isEmpty()))
                    inQObject << QString("%1: %2").arg(f, m.source);
        QVERIFY2(inQObject.isEmpty(), qPrintable(inQObject.join('\n')));
    }

    // Strings that were out of lupdate's reach, or built from pieces, each in the .ts whole.
    void theWrappedStringsAreFound_data()
    {
        QTest::addColumn<QString>("context");
        QTest::addColumn<QString>("source");
        QTest::addColumn<QString>("disambiguation");
        const QString phrases = "lb::ScenePhrases";
        // A variable given to tr(): the terms' keys, now marked.
        QTest::newRow("term key") << "lb::MainWindow"
                                  << "A"
                                  << "shortcut";
        // The status line's pieces, now whole phrases.
        QTest::newRow("light in its frame") << phrases << "point light in the camera frame"
                                            << "";
        QTest::newRow("projection") << phrases << "orthographic projection"
                                    << "";
        QTest::newRow("show choice") << phrases << "showing ndotl"
                                     << "show";
        // Help's " or " between keys, now a sentence with both keys in it.
        QTest::newRow("keys or keys") << "lb::Help"
                                      << "%1 or %2"
                                      << "";
        // Messages that were plain QStrings shown in the window.
        QTest::newRow("settings file") << "lb::SettingsAutosave"
                                       << "%1 cannot be written"
                                       << "";
        QTest::newRow("settings store") << "lb::SettingsStore"
                                        << "%1: cannot be written"
                                        << "";
        QTest::newRow("submission") << "lb::Submission"
                                    << "%1: the scene file has no program"
                                    << "";
        QTest::newRow("grading child") << "lb::WorkCheck"
                                       << "exit code %1"
                                       << "";
        QTest::newRow("program guard") << "lb::ProgramGuard"
                                       << "compiling this program and drawing it on small frames "
                                          "took more than %1: an endless or very long loop, or a "
                                          "program too big for the driver?"
                                       << "";
        QTest::newRow("check status") << "lb::MainWindow"
                                      << "Not checked: timed out"
                                      << "";
        QTest::newRow("new lesson") << "lb::UnsavedWork"
                                    << "Save the changes to %1 before starting a new lesson?"
                                    << "";
    }
    void theWrappedStringsAreFound()
    {
        QFETCH(QString, context);
        QFETCH(QString, source);
        QFETCH(QString, disambiguation);
        bool found = false;
        for (const Message &m : m_found)
            found = found || (m.context == context && m.source == source &&
                              m.disambiguation == disambiguation);
        QVERIFY2(found, qPrintable(QString("%1 / %2").arg(context, source)));
    }
};

QTEST_GUILESS_MAIN(TestTranslatableApp)
#include "test_translatable_app.moc"
