// The window in the students' languages (issue 31): in German and Portuguese the menus,
// panels, status line, messages and Qt's own buttons speak the language; every panel still
// fits 1024x768 and 1280x720 with no sideways scrolling, no label or button cut short and
// every tab name whole; View > Language keeps the choice and offers the restart it needs.
#include "window_fixture.h"

#include "help.h"
#include "language.h"
#include "language_menu.h"
#include "lesson.h"
#include "lesson_actions.h"
#include "lesson_bar.h"
#include "lesson_pointer.h"
#include "main_window_settings.h"
#include "object_panel.h"
#include "presets.h"
#include "scene_actions.h"

#include <QAbstractButton>
#include <QDockWidget>
#include <QFileDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTabBar>
#include <QTimer>

using namespace lb;
using namespace lb::test;

Q_DECLARE_METATYPE(QRect)

namespace {

QString withoutAccelerator(QString text)
{
    return text.replace("&&", "\x01").remove('&').replace("\x01", "&");
}

// Tabs (the docks' and the editor's) out of sight or too short for their names.
QStringList tabsCut(const QWidget &window)
{
    QStringList cut;
    for (const QTabBar *bar : window.findChildren<QTabBar *>()) {
        if (!bar->isVisibleTo(&window))
            continue;
        const bool vertical =
            bar->shape() == QTabBar::RoundedWest || bar->shape() == QTabBar::RoundedEast ||
            bar->shape() == QTabBar::TriangularWest || bar->shape() == QTabBar::TriangularEast;
        for (int i = 0; i < bar->count(); ++i) {
            const QRect r = bar->tabRect(i);
            const int room = vertical ? r.height() : r.width();
            const int needed =
                bar->fontMetrics().horizontalAdvance(withoutAccelerator(bar->tabText(i)));
            if (!bar->rect().contains(r) || room < needed)
                cut << QString("tab \"%1\" (%2 px for %3)")
                           .arg(bar->tabText(i))
                           .arg(room)
                           .arg(needed);
        }
    }
    return cut;
}

// Labels and buttons narrower than their text: cut mid-word. Labels that wrap, and the ones
// made to elide (the status line's, names of files), are left out.
QStringList controlsCut(const QWidget &panel, const QWidget &window)
{
    QStringList cut;
    for (const QLabel *label : panel.findChildren<QLabel *>()) {
        if (!label->isVisibleTo(&window) || label->wordWrap() || label->text().isEmpty() ||
            label->inherits("lb::ElidedLabel") || label->textFormat() == Qt::RichText)
            continue;
        if (label->width() < label->minimumSizeHint().width())
            cut << QString("label \"%1\" (%2 px for %3)")
                       .arg(label->text())
                       .arg(label->width())
                       .arg(label->minimumSizeHint().width());
    }
    for (const QAbstractButton *button : panel.findChildren<QAbstractButton *>()) {
        if (!button->isVisibleTo(&window) || button->text().isEmpty() ||
            button->inherits("QToolButton"))
            continue;
        if (button->width() < button->minimumSizeHint().width())
            cut << QString("button \"%1\" (%2 px for %3)")
                       .arg(button->text())
                       .arg(button->width())
                       .arg(button->minimumSizeHint().width());
    }
    return cut;
}

} // namespace

class TestWindowLanguages : public WindowTest
{
    Q_OBJECT

    // A window built after the language's translators are installed, as main() builds it.
    void showIn(const QString &language)
    {
        m_window.reset();
        removeTranslators(*qApp);
        const QStringList loaded = installTranslators(*qApp, language);
        if (language != "en")
            QVERIFY2(loaded.contains("lightbench") && loaded.contains("qt"),
                     qPrintable(loaded.join(", ")));
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    }
    void settle()
    {
        for (int i = 0; i < 5; ++i) {
            QCoreApplication::processEvents();
            QTest::qWait(40);
        }
    }
    QDockWidget *dock(const char *name) { return m_window->findChild<QDockWidget *>(name); }
    // Clicks the button of the modal box that opens next, by its text.
    void answerNextBox(const QString &button, QString *boxText)
    {
        QTimer::singleShot(200, this, [button, boxText] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            *boxText = box->text();
            for (QAbstractButton *b : box->buttons())
                if (b->text() == button)
                    return b->click();
            box->reject(); // no such button: the test fails on what it finds, not by waiting
            *boxText = "no button " + button + " in: " + box->text();
        });
    }

private slots:
    void cleanup()
    {
        m_window.reset();
        removeTranslators(*qApp);
    }

    void speaksTheLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QStringList>("expected"); // File, its first item, the Light dock,
        // the light panel's "Type", the status line's "Program:", the scene's message title,
        // Qt's Cancel button
        QTest::newRow("de") << "de" << QStringList{"&Datei",   "Szene ö&ffnen...", "Licht",
                                                   "Typ",      "Programm: ",       "Szene",
                                                   "Abbrechen"};
        QTest::newRow("pt") << "pt"
                            << QStringList{"&Ficheiro",  "&Abrir Cena...", "Luz",     "Tipo",
                                           "Programa: ", "Cena",           "Cancelar"};
        QTest::newRow("en") << "en" << QStringList{"&File",     "&Open Scene...", "Light", "Type",
                                                   "Program: ", "Scene",          "Cancel"};
    }
    void speaksTheLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QStringList, expected);
        showIn(language);
        QMenu *file = m_window->menuBar()->actions().value(0)->menu();
        QVERIFY(file);
        QCOMPARE(file->title(), expected[0]);
        QCOMPARE(file->actions().value(0)->text(), expected[1]);
        QCOMPARE(dock("lightDock")->windowTitle(), expected[2]);
        bool typeLabel = false;
        for (const QLabel *label : m_window->lightPanel()->findChildren<QLabel *>())
            typeLabel = typeLabel || label->text() == expected[3];
        QVERIFY2(typeLabel, qPrintable(expected[3]));
        QVERIFY2(m_window->statusLine()->programLabel()->text().startsWith(expected[4]),
                 qPrintable(m_window->statusLine()->programLabel()->text()));
        // A scene file that is not one: the message says so in the window's language.
        const QString broken = m_dir.filePath("broken.json");
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ \"format\": \"lightbench-scene\", ");
        f.close();
        m_window->sceneActions()->open(broken);
        QMessageBox *box = nullptr;
        QVERIFY(QTest::qWaitFor(
            [&] {
                for (QWidget *w : QApplication::topLevelWidgets())
                    if (auto *b = qobject_cast<QMessageBox *>(w); b && b->isVisible())
                        box = b;
                return box != nullptr;
            },
            5000));
        QCOMPARE(box->windowTitle(), expected[5]);
        box->close();
        // Qt's own words come from Qt's catalogue (qt6-translations-l10n).
        QMessageBox standard(QMessageBox::Question, "", "", QMessageBox::Cancel);
        QCOMPARE(standard.button(QMessageBox::Cancel)->text(), expected[6]);
        // Lessons and examples follow the window's language.
        QCOMPARE(lessonLanguage(), language);
        // Counts in sentences never group with the point the fields' decimals use (issue 49,
        // item 18): German's "1.024.000 Dreiecke" is written "1 024 000".
        const QString count = writtenCount(1024000);
        QVERIFY2(!count.contains('.'), qPrintable(count));
        if (language == "de")
            QCOMPARE(count, QString("1\u00a0024\u00a0000"));
        if (language == "en")
            QCOMPARE(count, QString("1,024,000"));
        // The Uniforms panel in Portuguese (issue 49, item 17); German keeps "Uniforms".
        QCOMPARE(dock("uniformDock")->windowTitle(),
                 QString(language == "pt" ? "Uniformes" : "Uniforms"));
    }

    // What was still English in the translated window (issue 49, item 17): the stage tabs and
    // the message list's stage, key names in the help, the file dialog's "Look in:", and the
    // names the shipped examples give their objects and program.
    void keysFilesAndNamesSpeakTheLanguage_data()
    {
        QTest::addColumn<QString>("language");
        // The fragment tab, the help's key for the next step, the file dialog's "Look in:",
        // the example's sphere, its textured cube, its program
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("pt") << "pt"
                            << QStringList{"Fragmentos",       "Page Down",
                                           "Procurar em:",     "esfera",
                                           "cubo com textura", "exercício (a sua resposta)"};
        QTest::newRow("de") << "de"
                            << QStringList{
                                   "Fragment", "Bild abwärts",        "Suchen in:",
                                   "Kugel",    "texturierter Würfel", "Aufgabe (Ihre Lösung)"};
        QTest::newRow("en") << "en" << QStringList{"Fragment",      "PgDown",
                                                   "Look in:",      "sphere",
                                                   "textured cube", "exercise (your answer)"};
    }
    void keysFilesAndNamesSpeakTheLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QStringList, expected);
        showIn(language);
        auto *tabs = m_window->editorPanel()->findChild<QTabWidget *>();
        QVERIFY(tabs);
        QCOMPARE(tabs->tabText(1), expected[0]);
        // Key names as the help and the menus write them (a lesson's keys are in its menu
        // while it runs); the help's completion key is Ctrl and Space's.
        const auto named = [](QKeySequence key) { return key.toString(QKeySequence::NativeText); };
        QCOMPARE(named(QKeySequence(Qt::Key_PageDown)), expected[1]);
        const QString help = shortcutsHtml(m_window->menuBar());
        const QString completion = named(QKeySequence(Qt::CTRL | Qt::Key_Space));
        QVERIFY2(help.contains(completion), qPrintable(completion));
        if (language == "pt") {
            QCOMPARE(completion, QString("Ctrl+Espaço"));
            for (Qt::Key key : {Qt::Key_PageUp, Qt::Key_Backspace, Qt::Key_Right})
                QVERIFY2(
                    !QRegularExpression("^(PgUp|Backspace|Right)$").match(named(key)).hasMatch(),
                    qPrintable(named(key)));
        }
        // Qt's own file dialog, as the window opens it where the desktop has none.
        {
            QFileDialog dialog(m_window.get()); // gone before the window below is
            dialog.setOption(QFileDialog::DontUseNativeDialog);
            auto *lookIn = dialog.findChild<QLabel *>("lookInLabel");
            QVERIFY(lookIn);
            QCOMPARE(lookIn->text(), expected[2]);
        }
        // The exercise example names its objects and program in each language.
        m_window->sceneActions()->open(":/examples/exercise_lighting.json");
        settle();
        QListWidget *objects = m_window->objectPanel()->objectList();
        QCOMPARE(objects->count(), 2);
        QCOMPARE(objects->item(0)->text(), expected[3]);
        QCOMPARE(objects->item(1)->text(), expected[4]);
        QVERIFY2(m_window->editorPanel()->programName().startsWith(expected[5]),
                 qPrintable(m_window->editorPanel()->programName()));
        QVERIFY(!m_window->sceneActions()->isModified()); // the names as read are the file's
        // Saved again, the file keeps every language's name (what the user renames is one).
        const QString saved = m_dir.filePath("exercise.json");
        QCOMPARE(m_window->sceneActions()->save(saved), QString());
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        for (const char *name : {"cubo com textura", "texturierter Würfel", "exercício (a sua"})
            QVERIFY2(bytes.contains(name), name);
        // The next start names the program as this one did (the session keeps its languages).
        m_window->saveSettings();
        m_window.reset();
        m_window = std::make_unique<MainWindow>(*m_settings);
        QVERIFY2(m_window->editorPanel()->programName().startsWith(expected[5]),
                 qPrintable(m_window->editorPanel()->programName()));
    }

    // The shipped lessons' captions name controls as the window labels them in its language
    // ({ui:NAME}), not by an English copy: in German the sheet's step 9 says "Arbeit prüfen"
    // as the menu does, the slides' first step in Portuguese the Probe panel's tab "Sonda"
    // (issue 49, item 16).
    void captionsNameControlsAsTheWindowDoes_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("lesson");
        QTest::addColumn<QString>("english"); // what the English window would say
        QTest::newRow("de sheet") << "de"
                                  << ":/lessons/exercise_sheet.json"
                                  << "Check My Work";
        QTest::newRow("pt slides") << "pt"
                                   << ":/lessons/slides.json"
                                   << "Probe panel";
        QTest::newRow("en sheet") << "en"
                                  << ":/lessons/exercise_sheet.json"
                                  << "";
    }
    void captionsNameControlsAsTheWindowDoes()
    {
        QFETCH(QString, language);
        QFETCH(QString, lesson);
        QFETCH(QString, english);
        showIn(language);
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        LessonActions *lessons = m_window->lessonActions();
        QVERIFY(lessons->open(lesson));
        int placeholders = 0;
        for (int i = 0; i < int(lessons->lesson().steps.size()); ++i) {
            lessons->goTo(i);
            QCoreApplication::processEvents();
            const QString caption = lessons->bar()->captionLabel()->text();
            QVERIFY2(!caption.contains("{ui:"), qPrintable(caption));
            if (!english.isEmpty())
                QVERIFY2(!caption.contains(english), qPrintable(caption));
            for (const QString &text : lessons->lesson().steps[std::size_t(i)].caption)
                placeholders += text.count("{ui:");
        }
        QVERIFY(placeholders > 0);
        // What each name stands for, as the window shows it now.
        QCOMPARE(withControlNames(*m_window, "{ui:probe}"), dock("probeDock")->windowTitle());
        QString check = m_window->checkAction()->text().remove('&');
        QCOMPARE(withControlNames(*m_window, "{ui:check}"), check + " (F9)");
        QCOMPARE(withControlNames(*m_window, "{ui:nothing.known}"), QString("{ui:nothing.known}"));
        if (language == "de")
            QCOMPARE(check, QString("Arbeit prüfen"));
        if (language == "pt")
            QCOMPARE(dock("probeDock")->windowTitle(), QString("Sonda"));
    }

    // The exercise sheet's step 9 in German on a 1024x768 screen: its caption whole in the
    // column between panels and editor, not three lines and a scrollbar (issue 49, item 14).
    void aLongGermanCaptionIsWholeAt1024()
    {
        showIn("de");
        m_window->fitToScreen(QRect(0, 0, 1024, 744));
        QVERIFY(m_window->lessonActions()->open(":/lessons/exercise_sheet.json", 8));
        settle();
        const QLabel *caption = m_window->lessonActions()->bar()->captionLabel();
        QVERIFY(caption->text().contains("Arbeit"));
        QVERIFY2(caption->height() <= caption->parentWidget()->height() + 1,
                 qPrintable(QString("caption %1 px in %2 px")
                                .arg(caption->height())
                                .arg(caption->parentWidget()->height())));
    }

    // The trial helper tries a program in its own process: a refusal it writes (an endless
    // loop, a class's most common mistake) reaches the editor and the banner in German too.
    void aRefusalFromTheTrialHelperSpeaksTheLanguage()
    {
        showIn("de");
        EditorPanel *e = m_window->editorPanel();
        QVERIFY(buildAfter([&] { e->loadPreset(presets()[3]); })); // the slides' Phong
        QString fragment = e->source(ShaderStage::Fragment);
        const int at = int(fragment.indexOf("    gl_FragColor"));
        QVERIFY(at > 0);
        fragment.insert(at, "    float k = N.x + 2.0;\n"
                            "    while (k > 0.0) { k = k * 1.0 + 0.0001; }\n"
                            "    diffuse *= k;\n");
        const std::optional<ProgramBuild> b =
            buildAfter([&] { e->editor(ShaderStage::Fragment)->setText(fragment); });
        QVERIFY(b && !b->ok() && !b->diagnostics.empty());
        // The helper's refusal over the budget, or (on a loaded machine) the window's own
        // time-out.
        const QString said = b->diagnostics.back().message;
        QVERIFY2(said.startsWith("ein Bild mit diesem Programm bei ") ||
                     said.startsWith("das Kompilieren dieses Programms"),
                 qPrintable(said));
        QVERIFY2(m_window->viewport()->banner().contains(said),
                 qPrintable(m_window->viewport()->banner()));
    }

    void fitsTheScreenInEveryLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QRect>("available");
        for (const char *language : {"en", "de", "pt"}) {
            // Screens less a 24-pixel panel, as a desktop's available area is.
            QTest::addRow("%s 1024x768", language) << language << QRect(0, 0, 1024, 744);
            QTest::addRow("%s 1280x720", language) << language << QRect(0, 0, 1280, 696);
        }
    }
    void fitsTheScreenInEveryLanguage()
    {
        QFETCH(QString, language);
        QFETCH(QRect, available);
        showIn(language);
        m_window->fitToScreen(available);
        settle();
        QVERIFY(available.contains(m_window->frameGeometry()));
        const QString sideways = docksNeedingSideways(*m_window);
        QVERIFY2(sideways.isEmpty(), qPrintable("horizontal scrollbar in " + sideways));
        // Every menu's title in the menu bar, none folded into its overflow button.
        const QMenuBar *bar = m_window->menuBar();
        for (QAction *menu : bar->actions())
            QVERIFY2(bar->rect().contains(bar->actionGeometry(menu)),
                     qPrintable(menu->text() + " is folded away"));
        QStringList cut = tabsCut(*m_window);
        for (QDockWidget *d : m_window->findChildren<QDockWidget *>()) {
            d->raise();
            settle();
            cut << controlsCut(*d, *m_window);
        }
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join("\n")));
        // A stage with a message gets its mark ("Fragmentos ●"): the tabs stay whole and the
        // Presets button (its symbol where its word does not fit) beside them, not over them.
        EditorPanel *e = m_window->editorPanel();
        QString fragment = e->source(ShaderStage::Fragment);
        fragment.replace("void main", "vec3 typo = vec3(1.0) +;\nvoid main");
        const std::optional<ProgramBuild> b =
            buildAfter([&] { e->editor(ShaderStage::Fragment)->setText(fragment); });
        QVERIFY(b && !b->ok());
        auto *tabs = e->findChild<QTabWidget *>();
        QVERIFY(tabs && tabs->tabText(1).endsWith(QString::fromUtf8("\u25cf")));
        e->parentWidget()->raise();
        settle();
        QVERIFY2(tabsCut(*m_window).isEmpty(), qPrintable(tabsCut(*m_window).join("\n")));
        const QWidget *presets = tabs->cornerWidget(Qt::TopLeftCorner);
        const QRect stageTabs(tabs->tabBar()->mapTo(tabs, QPoint()), tabs->tabBar()->size());
        QVERIFY2(!presets->geometry().intersects(stageTabs.adjusted(1, 0, 0, 0)),
                 qPrintable(QString("Presets %1 over the tabs %2")
                                .arg(presets->geometry().x())
                                .arg(stageTabs.x())));
        QCOMPARE(presets->accessibleName(), EditorPanel::tr("Presets"));
    }

    // View > Language: the choice is kept; "Later" leaves the window as it is, "Restart Now"
    // closes it (asking about unsaved work as Quit does) for main() to start it again.
    void choosingALanguageOffersARestart()
    {
        QMenu *languages = nullptr;
        for (QMenu *menu : m_window->findChildren<QMenu *>())
            if (menu->title() == "&Language")
                languages = menu;
        QVERIFY(languages);
        const auto choice = [&](const QString &code) {
            for (QAction *a : languages->actions())
                if (a->data().toString() == code)
                    return a;
            return static_cast<QAction *>(nullptr);
        };
        QVERIFY(choice("") && choice("en") && choice("pt") && choice("de"));
        QVERIFY(choice("")->isChecked()); // a fresh settings file follows the system

        QString asked;
        answerNextBox("&Later", &asked);
        choice("de")->trigger();
        QVERIFY2(asked.contains("Restart now?"), qPrintable(asked));
        QCOMPARE(m_settings->value(kInterfaceLanguageKey).toString(), QString("de"));
        QVERIFY(!restartRequested());
        QVERIFY(m_window->isVisible());

        asked.clear();
        answerNextBox("Restart &Now", &asked);
        choice("pt")->trigger();
        QVERIFY(!asked.isEmpty());
        QCOMPARE(m_settings->value(kInterfaceLanguageKey).toString(), QString("pt"));
        QVERIFY(restartRequested());
        QVERIFY(!m_window->isVisible());
        // What main() installs for the next start.
        QCOMPARE(resolvedLanguage(m_settings->value(kInterfaceLanguageKey).toString()),
                 QString("pt"));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowLanguages)
#include "test_window_languages.moc"
