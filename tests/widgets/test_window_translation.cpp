// The window's words come through Qt's translation system (issue 31). A test translator
// answers every lightbench text with a mark, "«context|source»" (arguments filled in after),
// and a few whole sentences with German-like ones, some in another order. What the window
// shows then tells a string left out of tr(), a sentence built from pieces (the translation
// of the whole never appears), a constant made before any translator was in, and a string
// compared in one context with what another context said.
// Bad inputs tried: a settings file under a regular file (no folder can be made), no
// temporary folder (TMPDIR=/proc), a side B folder without a shader pair, a grading child
// that crashes and one that exits 3, a report with a status the window must not show raw,
// a mesh load cancelled, a mesh file that is not there.
#include "help.h"
#include "lesson_actions.h"
#include "marking_translator.h"
#include "scene_phrases.h"
#include "settings_store.h"
#include "submission.h"
#include "unsaved_work.h"
#include "window_fixture.h"

#include "choice_labels.h"
#include "work_check.h"

#include <QFileDialog>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTimer>

using namespace lb;
using namespace lb::test;

namespace {

// The tests' MarkingTranslator, which marks every text with its context, with three changes:
// some whole sentences get a translation of their own; Qt's own words (key names, buttons)
// stay as they are; and a shortcut given to tr() ("Ctrl+S") stays a key.
class TestTranslator : public MarkingTranslator
{
public:
    // (context, source, disambiguation) -> translation
    QHash<QString, QString> words;
    void add(const char *context, const char *source, const QString &translation,
             const char *disambiguation = "")
    {
        words.insert(key(context, source, disambiguation), translation);
    }

    QString translate(const char *context, const char *source, const char *disambiguation,
                      int n) const override
    {
        if (!QByteArray(context).startsWith("lb::"))
            return {};
        if (const auto it = words.find(key(context, source, disambiguation)); it != words.end())
            return *it;
        const QString text = QString::fromUtf8(source);
        const QKeySequence key = QKeySequence::fromString(text, QKeySequence::PortableText);
        if (!key.isEmpty() && key.toString(QKeySequence::PortableText) == text)
            return {};
        return MarkingTranslator::translate(context, source, disambiguation, n);
    }

private:
    static QString key(const char *context, const char *source, const char *disambiguation)
    {
        return QString("%1\n%2\n%3")
            .arg(QString::fromUtf8(context), QString::fromUtf8(source),
                 QString::fromUtf8(disambiguation ? disambiguation : ""));
    }
};

} // namespace

class TestWindowTranslation : public WindowTest
{
    Q_OBJECT
    TestTranslator m_translator;

    // The text with the marks and the test's translations taken out: what no translator
    // reached. Marks nest (a translated name in a translated sentence).
    QString untranslated(QString text) const
    {
        for (const QString &word : m_translator.words)
            text.remove(word);
        QString rest;
        int depth = 0;
        for (const QChar c : text) {
            if (c == QChar(0x00ab))
                ++depth;
            else if (c == QChar(0x00bb))
                depth = std::max(depth - 1, 0);
            else if (depth == 0)
                rest += c;
        }
        return rest;
    }
    static bool hasWords(const QString &text)
    {
        for (const QChar c : text)
            if (c.isLetter())
                return true;
        return false;
    }

private slots:
    void initTestCase()
    {
        // Whole sentences and phrases in another language, some of them reordered.
        TestTranslator &t = m_translator;
        t.add("lb::ScenePhrases", "point light in the world frame", "Punktlicht im Weltsystem");
        t.add("lb::ScenePhrases", "directional light in the camera frame",
              "Richtungslicht im Kamerasystem");
        t.add("lb::ScenePhrases", "perspective projection", "Zentralprojektion");
        t.add("lb::ScenePhrases", "%1, %2", "%1; %2");
        t.add("lb::ScenePhrases", "%1  |  %2  |  %3", "%3 / %2 / %1");
        t.add("lb::Scene", "sphere", "Kugel");
        t.add("lb::Help", "%1 or %2", "%2 oder %1");
        t.add("lb::Help", "View", "Ansicht");
        t.add("lb::UnsavedWork", "Save the changes to %1 before starting a new lesson?",
              "Vor einer neuen Lektion die \u00c4nderungen an %1 speichern?");
        t.add("lb::UnsavedWork", "the lesson \u201c%1\u201d", "der Lektion \u201e%1\u201c");
        t.add("lb::SettingsAutosave", "%1 cannot be written", "%1 ist nicht schreibbar");
        t.add("lb::SettingsStore",
              "no temporary folder for the settings (%1): they are written directly",
              "kein tempor\u00e4rer Ordner (%1)");
        t.add("lb::SettingsStore", "%1: cannot be written", "%1: nicht schreibbar");
        t.add("lb::MainWindow", "Not checked: timed out", "Nicht gepr\u00fcft: zu lange");
        t.add("lb::SceneActions", "Scenes (*.lbscene *.json);;All files (*)",
              "Szenen (*.lbscene *.json);;Alle Dateien (*)");
        QVERIFY(QCoreApplication::installTranslator(&m_translator));
    }
    void cleanupTestCase() { QCoreApplication::removeTranslator(&m_translator); }

    // Every menu item and its tooltip comes from the translator, but the languages (View >
    // Language, Lesson > Caption Language), each named in itself so that it is found whatever
    // the window speaks.
    void menusAreTranslated()
    {
        const QStringList endonyms = {"English", "Português", "Deutsch"};
        QStringList left;
        std::function<void(const QMenu *)> walk = [&](const QMenu *menu) {
            if (hasWords(untranslated(menu->title())))
                left << menu->title();
            for (const QAction *a : menu->actions()) {
                if (a->menu())
                    walk(a->menu());
                else if (!a->isSeparator() && !endonyms.contains(QString(a->text()).remove('&')) &&
                         (hasWords(untranslated(a->text())) ||
                          hasWords(untranslated(a->toolTip()))))
                    left << a->text() + " / " + a->toolTip();
            }
        };
        for (const QAction *a : m_window->menuBar()->actions())
            walk(a->menu());
        QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
        QVERIFY2(!hasWords(untranslated(m_window->windowTitle())),
                 qPrintable(m_window->windowTitle()));
    }

    // The status line: the light and the projection as whole phrases, the program's clauses
    // joined and the three places ordered as the translation says; nothing left in English.
    void statusLineIsTranslatedWhole()
    {
        auto status = [this] { return m_window->statusLine()->programLabel()->text(); };
        QVERIFY2(status().startsWith("Zentralprojektion / Punktlicht im Weltsystem / "),
                 qPrintable(status()));
        QVERIFY2(
            status().contains("; " + marked("lb::ScenePhrases", "Blinn-Phong (N\u00b7H) specular")),
            qPrintable(status()));
        QVERIFY2(!hasWords(untranslated(status())), qPrintable(untranslated(status())));
        m_window->document().edit([](Scene &s) {
            s.lights[0].frame = LightFrame::Camera;
            s.lights[0].position.w = 0.0f;
            s.shading.projection = Projection::Orthographic;
            s.shading.show = ShowChoice::NDotL;
            s.shading.shading = Shading::Flat;
        });
        QVERIFY2(status().contains(" / Richtungslicht im Kamerasystem / "), qPrintable(status()));
        QVERIFY2(status().startsWith(marked("lb::ScenePhrases", "orthographic projection")),
                 qPrintable(status()));
        QVERIFY2(status().contains(marked("lb::ScenePhrases", "showing ndotl")),
                 qPrintable(status()));
        QVERIFY2(!hasWords(untranslated(status())), qPrintable(untranslated(status())));
    }

    // Names put into sentences are the window's words: English as the files spell them,
    // translated where shown (here: the shape drawn for a mesh file that is not there).
    void namesInSentencesAreTheWindowsWords()
    {
        QCoreApplication::removeTranslator(&m_translator);
        for (Shading v : {Shading::Gouraud, Shading::Phong, Shading::Flat})
            QCOMPARE(shadingLabel(v), toName(v));
        for (SpecularModel v : {SpecularModel::Phong, SpecularModel::Blinn})
            QCOMPARE(specularLabel(v), toName(v));
        QVERIFY(QCoreApplication::installTranslator(&m_translator));
        QCOMPARE(shadingLabel(Shading::Phong), marked("lb::ChoiceLabels", "phong"));

        const QString gone = m_dir.filePath("away.ply");
        m_window->document().edit([&](Scene &s) {
            s.objects[0].shape = Shape::Sphere;
            s.objects[0].meshPath = gone;
        });
        QTRY_COMPARE(m_window->meshActions()->summaryLabel()->text(),
                     marked("lb::MeshActions", "away.ply not loaded (Kugel drawn)"));
    }

    // Help > Keyboard Shortcuts: two keys for one action are one sentence a translation may
    // reorder, not the keys joined by a translated " or ".
    void helpSaysAlternativesWhole()
    {
        const QString html = shortcutsHtml(m_window->menuBar());
        // Presentation mode's three: F11, F5 and Shift+F5 ("Umschalt+F5" in German).
        const QRegularExpressionMatch keys =
            QRegularExpression("<b>([^<]*F5[^<]*)</b>").match(html);
        QVERIFY(keys.hasMatch());
        QVERIFY2(keys.captured(1).contains(" oder ") && keys.captured(1).contains("F11") &&
                     keys.captured(1).count("F5") == 2,
                 qPrintable(keys.captured(1)));
        QVERIFY2(html.contains("<h3>Ansicht</h3>"), qPrintable(html));
        QVERIFY2(!html.contains("F11 or F5"), qPrintable(html));
    }

    // A new lesson over a changed one: its own question, whole.
    void newLessonAsksItsOwnQuestion()
    {
        QStringList asked;
        m_window->setUnsavedWorkAsker([&](QWidget *, const QString &question, const QString &) {
            asked << question;
            return QMessageBox::Cancel;
        });
        LessonActions *lessons = m_window->lessonActions();
        lessons->newLesson(); // nothing to ask about yet
        QVERIFY(lessons->isModified());
        lessons->newLesson();
        QCOMPARE(asked.size(), 1);
        QCOMPARE(asked[0],
                 QString("Vor einer neuen Lektion die \u00c4nderungen an der Lektion "
                         "\u201e\u00ablb::LessonActions|untitled lesson\u00bb\u201c speichern?"));
        m_window->setUnsavedWorkAsker({});
    }

    // The settings' messages reach the status line translated, each a whole sentence.
    void settingsMessagesAreTranslated()
    {
        // A file under a regular file: its folder cannot be made.
        QFile blocker(m_dir.filePath("blocker"));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        const QString path = m_dir.filePath("blocker/settings.ini");
        {
            QSettings settings(path, QSettings::IniFormat);
            SettingsAutosave autosave(settings, m_window->statusLine(),
                                      [&] { settings.setValue("x", 1); });
            autosave.saveNow();
            const QString message = m_window->statusLine()->message();
            QVERIFY2(message.contains(path + " ist nicht schreibbar"), qPrintable(message));
            QVERIFY2(!hasWords(untranslated(message).remove(path)), qPrintable(message));
        }
        // No temporary folder: the store says so, and then that it cannot write the file.
        const bool hadTmp = qEnvironmentVariableIsSet("TMPDIR");
        const QByteArray tmp = qgetenv("TMPDIR");
        // /proc takes no new folder, not even root's (a missing TMPDIR means the current one).
        qputenv("TMPDIR", "/proc");
        SettingsStore store(path);
        if (hadTmp)
            qputenv("TMPDIR", tmp);
        else
            qunsetenv("TMPDIR");
        QVERIFY2(store.error().startsWith("kein tempor\u00e4rer Ordner ("),
                 qPrintable(store.error()));
        store.settings().setValue("x", 1);
        QCOMPARE(store.save(), path + ": nicht schreibbar");
    }

    // Side B and Check My Work: their messages, the box's title and what a grading child's
    // end says, through the translator; a report's status is said in a sentence, never raw.
    void sideBAndCheckMessagesAreTranslated()
    {
        const QString folder = m_dir.filePath("no-pair");
        QVERIFY(QDir().mkpath(folder));
        const QString message = m_window->setSideBFiles(folder);
        QVERIFY2(
            message.startsWith("\u00ablb::MainWindow|Side B is unchanged: \u00ablb::Submission|" +
                               folder + ": a folder needs one NAME.vert"),
            qPrintable(message));
        auto *box = m_window->findChild<QMessageBox *>("sideBMessage");
        QVERIFY(box);
        QCOMPARE(box->windowTitle(), marked("lb::MainWindow", "Side B"));
        box->close();

        GradingReport report;
        report.status = "timed out";
        emit m_window->workCheck()->finished(report);
        QCOMPARE(m_window->statusLine()->message(), QString("Nicht gepr\u00fcft: zu lange"));

        QProcess crash;
        crash.start("/bin/sh", {"-c", "kill -SEGV $$"});
        QVERIFY(crash.waitForFinished(10000));
        QVERIFY2(endedWithoutReport(crash).startsWith("\u00ablb::WorkCheck|killed by signal 11 ("),
                 qPrintable(endedWithoutReport(crash)));
        QProcess exit3;
        exit3.start("/bin/sh", {"-c", "exit 3"});
        QVERIFY(exit3.waitForFinished(10000));
        QCOMPARE(endedWithoutReport(exit3), marked("lb::WorkCheck", "exit code 3"));
    }

    // The scene dialog's filter is translated when the dialog opens, not made once before
    // any translator was installed.
    void sceneDialogFilterIsTranslated()
    {
        QStringList filters;
        QTimer poll;
        connect(&poll, &QTimer::timeout, this, [&] {
            if (auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget())) {
                filters = dialog->nameFilters();
                dialog->reject();
            }
        });
        poll.start(20);
        QAction *open = nullptr;
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->shortcut() == QKeySequence(QKeySequence::Open))
                open = a;
        QVERIFY(open);
        open->trigger(); // returns once the dialog is rejected
        QCOMPARE(filters, QStringList({"Szenen (*.lbscene *.json)", "Alle Dateien (*)"}));
    }

    // A cancelled load says so on the status line and is no error, also when the loader's
    // words are translated: the window compares them in the loader's own context.
    void cancelledLoadIsNoErrorInAnyLanguage()
    {
        const QString helper = writeSlowImportHelper(m_dir);
        QVERIFY(!helper.isEmpty());
        const QByteArray saved = qgetenv("LIGHTBENCH_IMPORT_HELPER");
        qputenv("LIGHTBENCH_IMPORT_HELPER", helper.toLocal8Bit());
        QSignalSpy finished(m_window->objectLoader(), &ObjectLoader::loadFinished);
        m_window->meshActions()->open(kCube);
        LoadProgress *progress = m_window->meshActions()->progress();
        QTRY_VERIFY_WITH_TIMEOUT(progress->isVisible(), 3000);
        QTest::mouseClick(progress->cancelButton(), Qt::LeftButton);
        QTRY_COMPARE(finished.count(), 1);
        qputenv("LIGHTBENCH_IMPORT_HELPER", saved);
        QCOMPARE(finished[0][1].toString(), marked("lb::ObjectLoader", "Loading cancelled"));
        QVERIFY(!m_window->meshActions()->errorBox());
        QCOMPARE(m_window->statusLine()->message(),
                 marked("lb::ObjectLoader", "Loading cancelled"));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowTranslation)
#include "test_window_translation.moc"
