// Ask before discarding (issue 28): quit, close, another scene (File > Open Scene, Open
// Recent Scene, Examples, a dropped file) and Reset Everything ask Save / Discard / Cancel
// while the title shows *. The real message box is asked, and answered here.
#include "window_fixture.h"

#include "unsaved_work.h"

#include <QFileDialog>
#include <QMenuBar>
#include <QTimer>

#include <deque>

using namespace lb;
using namespace lb::test;

namespace {

float shininessIn(const QString &path)
{
    const SceneFileRead read = readSceneFile(path);
    return read.file ? read.file->scene.objects[0].material.shininess : -1.0f;
}

QAction *menuAction(QMenu *menu, const QString &text)
{
    for (QAction *a : menu->actions()) {
        if (a->text().remove('&') == text)
            return a;
        if (a->menu())
            if (QAction *inner = menuAction(a->menu(), text))
                return inner;
    }
    return nullptr;
}

} // namespace

class TestWindowDiscard : public WindowTest
{
    Q_OBJECT
private:
    struct Asked
    {
        QString text, details;
        bool saveIsDefault = false, cancelIsEscape = false;
    };
    QList<Asked> m_asked;
    // The modal dialogs to answer, in order; each step says whether the widget was its own.
    std::deque<std::function<bool(QWidget *)>> m_answers;
    QTimer m_answerer;
    QString m_mine, m_other; // scene files: mine (shininess 20, edited to 77), other (5)

    // The question, answered with `button`.
    void answer(QMessageBox::StandardButton button)
    {
        m_answers.push_back([this, button](QWidget *w) {
            auto *box = qobject_cast<QMessageBox *>(w);
            if (!box || box->objectName() != "unsavedWorkQuestion")
                return false;
            m_asked.push_back({box->text(), box->informativeText(),
                               box->defaultButton() == box->button(QMessageBox::Save),
                               box->escapeButton() == box->button(QMessageBox::Cancel)});
            box->button(button)->click();
            return true;
        });
        startAnswering();
    }
    // A file dialog: `path` chosen, or cancelled when empty.
    void answerFileDialog(const QString &path)
    {
        m_answers.push_back([path](QWidget *w) {
            auto *dialog = qobject_cast<QFileDialog *>(w);
            if (!dialog)
                return false;
            if (path.isEmpty()) {
                dialog->reject();
            } else {
                dialog->selectFile(path);
                static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept(), protected
            }
            return true;
        });
        startAnswering();
    }
    void startAnswering()
    {
        m_answerer.setInterval(20);
        if (!m_answerer.isActive())
            m_answerer.start();
    }
    void answerNow()
    {
        QWidget *modal = QApplication::activeModalWidget();
        if (modal && !m_answers.empty() && m_answers.front()(modal))
            m_answers.pop_front();
    }

    // A window on mine.json (shininess 20) edited to 77, other.json (5) in Open Recent, and
    // the message box as the asker.
    void prepare()
    {
        m_window->setUnsavedWorkAsker(askAboutUnsavedWork);
        m_other = QFileInfo(m_dir.filePath("other.json")).absoluteFilePath();
        m_mine = QFileInfo(m_dir.filePath("mine.json")).absoluteFilePath();
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 5; });
        QCOMPARE(m_window->sceneActions()->save(m_other), QString());
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 20; });
        QCOMPARE(m_window->sceneActions()->save(m_mine), QString());
        QVERIFY(!m_window->isWindowModified());
        m_window->sceneActions()->recent()->add(m_other); // mine first, then other: keep both
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 77; });
        QVERIFY(m_window->isWindowModified());
    }

    // An entry of Open Recent Scene (choosing one rebuilds the menu: find it first).
    QAction *recentAction(const QString &name)
    {
        for (QAction *a : m_window->sceneActions()->recent()->actions())
            if (a->text().contains(name))
                return a;
        return nullptr;
    }

    // Does what a user does to set the work aside one way.
    void setAside(const QString &way)
    {
        QMenu *file = m_window->menuBar()->actions().first()->menu();
        if (way == "close") {
            m_window->close();
        } else if (way == "quit key") {
            QTest::keyClick(m_window.get(), Qt::Key_Q, Qt::ControlModifier);
        } else if (way == "open dialog") {
            menuAction(file, "Open Scene...")->trigger();
        } else if (way == "recent") {
            recentAction("other.json")->trigger();
        } else if (way == "example") {
            menuAction(file, "Toon shading")->trigger();
        } else if (way == "drop") {
            QMimeData mime;
            mime.setUrls({QUrl::fromLocalFile(m_other)});
            QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                                  Qt::NoModifier);
            QApplication::sendEvent(m_window.get(), &enter); // Qt delivers no drop without it
            QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(m_window.get(), &drop);
            QVERIFY(drop.isAccepted());
            // The question comes after the drop, not inside it.
            QCOMPARE(m_window->sceneActions()->currentPath(), m_mine);
        } else if (way == "reset") {
            menuAction(file, "Reset Everything")->trigger();
        }
        // Answered in order; a dropped file is opened after the drop.
        QTRY_VERIFY_WITH_TIMEOUT(m_answers.empty(), 10000);
        QCoreApplication::processEvents();
        m_answerer.stop();
    }

    bool wentAhead(const QString &way)
    {
        if (way == "close" || way == "quit key")
            return !m_window->isVisible();
        if (way == "example")
            return m_window->sceneActions()->documentName() == "toon.json";
        if (way == "reset")
            return m_window->sceneActions()->documentName().isEmpty() &&
                   scene().objects[0].material.shininess == Scene{}.objects[0].material.shininess;
        return m_window->sceneActions()->currentPath() == m_other &&
               scene().objects[0].material.shininess == 5.0f;
    }

private slots:
    void initTestCase()
    {
        connect(&m_answerer, &QTimer::timeout, this, &TestWindowDiscard::answerNow);
    }

    void cleanup()
    {
        m_answerer.stop();
        m_answers.clear();
        m_asked.clear();
        WindowTest::cleanup();
    }

    void eachWayAsks_data()
    {
        QTest::addColumn<QString>("way");
        QTest::addColumn<int>("button");
        const QString ways[] = {"close",   "quit key", "open dialog", "recent",
                                "example", "drop",     "reset"};
        const std::pair<QString, QMessageBox::StandardButton> answers[] = {
            {"cancel", QMessageBox::Cancel},
            {"discard", QMessageBox::Discard},
            {"save", QMessageBox::Save}};
        for (const QString &way : ways)
            for (const auto &[name, button] : answers)
                QTest::newRow(qPrintable(way + ", " + name)) << way << int(button);
    }

    // Cancel keeps the edit and the window as they are; Discard goes ahead without saving;
    // Save writes the scene file, then goes ahead.
    void eachWayAsks()
    {
        QFETCH(QString, way);
        QFETCH(int, button);
        prepare();
        if (way == "open dialog")
            answerFileDialog(m_other);
        answer(QMessageBox::StandardButton(button));
        setAside(way);

        QCOMPARE(m_asked.size(), 1);
        const Asked &asked = m_asked.first();
        QVERIFY2(asked.text.contains("\u201cmine.json\u201d"), qPrintable(asked.text));
        const QString target = way == "example"                      ? "Toon shading"
                               : way == "reset"                      ? "resetting everything"
                               : way == "close" || way == "quit key" ? "before closing"
                                                                     : "\u201cother.json\u201d";
        QVERIFY2(asked.text.contains(target), qPrintable(asked.text));
        QVERIFY(asked.details.contains("lost if you don't save"));
        QVERIFY(asked.saveIsDefault); // Return saves; nothing is thrown away by a slip
        QVERIFY(asked.cancelIsEscape);

        if (button == QMessageBox::Cancel) {
            QVERIFY(!wentAhead(way));
            QVERIFY(m_window->isVisible());
            QCOMPARE(scene().objects[0].material.shininess, 77.0f);
            QCOMPARE(m_window->sceneActions()->currentPath(), m_mine);
            QVERIFY(m_window->isWindowModified());
            QVERIFY(m_window->windowTitle().startsWith("mine.json"));
            QCOMPARE(shininessIn(m_mine), 20.0f);
            return;
        }
        QVERIFY(wentAhead(way));
        QCOMPARE(shininessIn(m_mine), button == QMessageBox::Save ? 77.0f : 20.0f);
        if (way != "close" && way != "quit key")
            return;
        // The next start: mine.json as saved. After Discard the edit does not come back.
        m_window.reset();
        m_window = std::make_unique<MainWindow>(*m_settings);
        QCOMPARE(m_window->sceneActions()->currentPath(), m_mine);
        QCOMPARE(scene().objects[0].material.shininess,
                 button == QMessageBox::Save ? 77.0f : 20.0f);
        QVERIFY(!m_window->isWindowModified());
    }

    void nothingAsksWhenNothingIsModified()
    {
        int asked = 0;
        m_window->setUnsavedWorkAsker([&](QWidget *, const QString &, const QString &) {
            ++asked;
            return QMessageBox::Cancel;
        });
        const QString other = m_dir.filePath("other.json");
        QCOMPARE(m_window->sceneActions()->save(other), QString());
        QMenu *file = m_window->menuBar()->actions().first()->menu();
        menuAction(file, "Toon shading")->trigger();
        QCOMPARE(m_window->sceneActions()->documentName(), QString("toon.json"));
        recentAction("other.json")->trigger();
        QCOMPARE(m_window->sceneActions()->documentName(), QString("other.json"));
        menuAction(file, "Reset Everything")->trigger();
        QCOMPARE(m_window->sceneActions()->documentName(), QString());
        m_window->close();
        QVERIFY(!m_window->isVisible());
        QCOMPARE(asked, 0);
    }

    // An untitled scene is saved through Save As; cancelling that dialog cancels the whole
    // action.
    void untitledSceneIsSavedAs()
    {
        m_window->setUnsavedWorkAsker(askAboutUnsavedWork);
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 77; });
        QVERIFY(m_window->isWindowModified());
        QMenu *file = m_window->menuBar()->actions().first()->menu();

        answer(QMessageBox::Save);
        answerFileDialog({});
        menuAction(file, "Reset Everything")->trigger();
        QVERIFY(m_answers.empty());
        QVERIFY2(m_asked.first().text.contains("the untitled scene"),
                 qPrintable(m_asked.first().text));
        QCOMPARE(scene().objects[0].material.shininess, 77.0f); // not reset
        QVERIFY(m_window->isWindowModified());

        const QString path = m_dir.filePath("named.json");
        answer(QMessageBox::Save);
        answerFileDialog(path);
        menuAction(file, "Reset Everything")->trigger();
        QVERIFY(m_answers.empty());
        QCOMPARE(shininessIn(path), 77.0f);
        QCOMPARE(scene().objects[0].material.shininess, Scene{}.objects[0].material.shininess);
    }

    // A save that fails says why and cancels: the window stays.
    void failedSaveCancels()
    {
        prepare();
        QVERIFY(QFile::remove(m_mine));
        QVERIFY(QDir().mkdir(m_mine)); // a folder where the file was: it cannot be replaced
        answer(QMessageBox::Save);
        setAside("close");
        QVERIFY(m_window->isVisible());
        QVERIFY(m_window->isWindowModified());
        QMessageBox *box = m_window->sceneActions()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains("not saved"), qPrintable(box->text()));
    }

    // An untitled scene whose program is a shader pair: the files are what is asked about,
    // and what Save writes; after Discard the next start shows them as on disk.
    void shaderFilesAreAskedAbout()
    {
        m_window->setUnsavedWorkAsker(askAboutUnsavedWork);
        const QString base = m_dir.filePath("pair");
        const Preset &toon = presets().back();
        for (const auto &[suffix, text] :
             {std::pair{".vert", toon.vertexSource()}, std::pair{".frag", toon.fragmentSource()}}) {
            QFile f(base + suffix);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text.toUtf8());
        }
        QCOMPARE(m_window->shaderDocument().openFiles({base + ".vert"}), QString());
        QVERIFY(!m_window->isWindowModified()); // opened, not edited: nothing to ask
        const QString edited = toon.fragmentSource() + "\n// edited\n";
        m_window->shaderDocument().setSource(ShaderStage::Fragment, edited);
        QVERIFY(m_window->isWindowModified());
        QCOMPARE(m_window->unsavedWork().shaderFiles, QStringList{"pair.frag"});
        QVERIFY(!m_window->unsavedWork().scene);

        answer(QMessageBox::Discard);
        setAside("close");
        QVERIFY2(m_asked.first().text == "Save the changes to the shader file pair.frag before "
                                         "closing?",
                 qPrintable(m_asked.first().text));
        QVERIFY(!m_window->isVisible());
        m_window.reset();
        m_window = std::make_unique<MainWindow>(*m_settings);
        QCOMPARE(m_window->shaderDocument().source(ShaderStage::Fragment), toon.fragmentSource());
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(m_window->shaderDocument().filePath(ShaderStage::Fragment),
                 QFileInfo(base + ".frag").absoluteFilePath());

        m_window->setUnsavedWorkAsker(askAboutUnsavedWork);
        m_window->shaderDocument().setSource(ShaderStage::Fragment, edited);
        answer(QMessageBox::Save);
        setAside("close");
        QVERIFY(!m_window->isVisible());
        QFile frag(base + ".frag");
        QVERIFY(frag.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(frag.readAll()), edited);
    }

    void questionNamesWhatIsUnsaved()
    {
        UnsavedWork work{true, {}, {"pair.vert", "pair.frag"}};
        QCOMPARE(unsavedWorkQuestion(work, SetAsideFor::OpeningScene, "toon.json"),
                 QString("Save the changes to the untitled scene and the shader files pair.vert "
                         "and pair.frag before opening \u201ctoon.json\u201d?"));
        QVERIFY(unsavedWorkDetails(work).contains("Save saves them all"));
        work.shaderFiles.clear();
        work.sceneName = "lesson.json";
        QCOMPARE(unsavedWorkQuestion(work, SetAsideFor::ResettingEverything),
                 QString("Save the changes to the scene \u201clesson.json\u201d before "
                         "resetting everything?"));
        QVERIFY(!unsavedWorkDetails(work).contains("them all"));
    }

    // A run without a user (no asker: tests, --screenshot, --bench-edits) never waits.
    void withNoOneToAskNothingWaits()
    {
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 77; });
        QVERIFY(m_window->isWindowModified());
        m_window->close();
        QVERIFY(!m_window->isVisible());
    }

    // A scripted --screenshot run of an edited scene exits without waiting on a question;
    // the scene file is untouched.
    void scriptedScreenshotDoesNotWait()
    {
        const QString scene = m_dir.filePath("scripted.json");
        QCOMPARE(m_window->sceneActions()->save(scene), QString());
        QTemporaryDir config;
        const QString png = config.filePath("shot.png");
        QByteArray err;
        QCOMPARE(runLightbench({"--scene", scene, "--shininess", "77", "--screenshot", png},
                               config.path(), &err),
                 0); // -1: the scripted run waited
        QVERIFY(QFile::exists(png));
        QVERIFY2(err.contains("closed without asking"), err.constData());
        QCOMPARE(shininessIn(scene), Scene{}.objects[0].material.shininess);
    }
};

int main(int argc, char **argv)
{
    // Qt's own file dialog, whatever the desktop: the test answers it.
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    TestWindowDiscard test;
    return lb::test::runWindowTest(test, argc, argv);
}

#include "test_window_discard.moc"
