// The window's translations are whole (issue 31): lupdate over today's sources finds no string
// that resources/translations/*.ts lacks (new, unfinished) and none that the sources lost
// (vanished); every translation keeps its source's placeholders, HTML tags, accelerator and
// outer spaces, so that no German or Portuguese text drops a number, breaks a rich label or
// gives a menu two accelerators. A new tr() without a translation fails here.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace {

struct Message
{
    QString context, source, type;
    bool numerus = false;
    QStringList translations; // one, or the plural forms
};

QList<Message> readTs(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<Message> messages;
    QString context;
    bool numerus = false;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == u"name") {
            context = xml.readElementText();
        } else if (xml.name() == u"message") {
            numerus = xml.attributes().value("numerus") == u"yes";
            messages.append({context, {}, {}, numerus, {}});
        } else if (messages.isEmpty()) {
            continue;
        } else if (xml.name() == u"source") {
            messages.last().source = xml.readElementText();
        } else if (xml.name() == u"translation") {
            messages.last().type = xml.attributes().value("type").toString();
            if (!numerus) // plural forms come as numerusform elements inside
                messages.last().translations << xml.readElementText();
        } else if (xml.name() == u"numerusform") {
            messages.last().translations << xml.readElementText();
        }
    }
    if (xml.hasError())
        *error = xml.errorString();
    return messages;
}

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

QSet<QString> asSet(const QStringList &list)
{
    return QSet<QString>(list.begin(), list.end());
}

QStringList all(const QString &text, const QRegularExpression &re)
{
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured(0);
    return found;
}

// What a translation must keep of its source; empty when it does.
QString broken(const QString &source, const QString &translation)
{
    static const QRegularExpression placeholder("%(L?[1-9]|n)");
    static const QRegularExpression tag("</?[a-zA-Z][a-zA-Z0-9]*");
    if (translation.trimmed().isEmpty() && !source.trimmed().isEmpty())
        return "empty";
    if (asSet(all(source, placeholder)) != asSet(all(translation, placeholder)))
        return "placeholders differ";
    if (sorted(all(source, tag)) != sorted(all(translation, tag)))
        return "HTML tags differ";
    const auto accelerators = [](QString s) { return s.remove("&&").count('&'); };
    if (!source.contains('<') && accelerators(source) != accelerators(translation))
        return "accelerators differ";
    const auto lead = [](const QString &s) { return !s.isEmpty() && s.front().isSpace(); };
    const auto trail = [](const QString &s) { return !s.isEmpty() && s.back().isSpace(); };
    if (lead(source) != lead(translation) || trail(source) != trail(translation))
        return "spaces around differ";
    return {};
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private slots:
    void translationsAreWholeAndCurrent_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<bool>("pluralsOnly"); // English: the sources' words, its plural forms
        QTest::newRow("de") << "de" << false;
        QTest::newRow("pt") << "pt" << false;
        QTest::newRow("en") << "en" << true;
    }
    void translationsAreWholeAndCurrent()
    {
        QFETCH(QString, language);
        QFETCH(bool, pluralsOnly);
        const QString name = QString("lightbench_%1.ts").arg(language);
        QTemporaryDir dir;
        const QString copy = dir.filePath(name);
        QVERIFY(QFile::copy(QString(LB_SOURCE_DIR "/resources/translations/") + name, copy));
        // lupdate over the sources, keeping what vanished (marked) so that it shows.
        QProcess lupdate;
        lupdate.setWorkingDirectory(LB_SOURCE_DIR);
        lupdate.start(LB_LUPDATE, {"app", "widgets", "render", "-locations", "none", "-ts", copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QVERIFY2(lupdate.exitCode() == 0, lupdate.readAllStandardError().constData());

        QString error;
        const QList<Message> messages = readTs(copy, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(messages.size() > 500);
        QStringList unfinished, vanished, wrong;
        for (const Message &m : messages) {
            const QString where = QString("%1: \"%2\"").arg(m.context, m.source.left(60));
            if (m.type == "unfinished" && (!pluralsOnly || m.numerus))
                unfinished << where;
            else if (m.type == "unfinished")
                continue; // English: the source is the text
            else if (m.type == "vanished" || m.type == "obsolete")
                vanished << where;
            else
                for (const QString &t : m.translations)
                    if (const QString why = broken(m.source, t); !why.isEmpty())
                        wrong << QString("%1 -> \"%2\": %3").arg(where, t.left(60), why);
        }
        const auto list = [](const QStringList &l) { return l.mid(0, 20).join("\n  "); };
        QVERIFY2(unfinished.isEmpty(),
                 qPrintable(QString("%1 strings have no %2 translation (run `cmake --build build "
                                    "--target update_translations`, then translate them):\n  %3")
                                .arg(unfinished.size())
                                .arg(language, list(unfinished))));
        QVERIFY2(vanished.isEmpty(),
                 qPrintable(QString("%1 translations are of strings the sources no longer have "
                                    "(update_translations drops them):\n  %2")
                                .arg(vanished.size())
                                .arg(list(vanished))));
        QVERIFY2(wrong.isEmpty(),
                 qPrintable(QString("%1 translations lose part of their source:\n  %2")
                                .arg(wrong.size())
                                .arg(list(wrong))));
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "test_translations.moc"
