// Lesson files in the window: broken lessons and steps, authoring and saving, the question
// about unsaved changes, a dropped lesson, and --lesson F --step N.
#include "lesson_fixture.h"

using namespace lb;
using namespace lb::test;

class TestWindowLessonFiles : public LessonWindowTest
{
    Q_OBJECT
private slots:
    // A lesson that cannot be read changes nothing and says why; one with broken steps (a
    // scene file that is missing, one that is a FIFO) opens, names them once, and a broken
    // step shows its reason in the bar with the scene left as it was.
    void brokenLessonsAreNamed()
    {
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 42; });
        const Scene before = scene();
        const QString broken = m_dir.filePath("broken.json");
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"format\": \"lightbench-lesson\", \"steps\": [");
        f.close();
        QVERIFY(!lessons()->open(broken));
        QVERIFY(!lessons()->isOpen());
        QVERIFY(!lessons()->bar()->isVisible());
        QVERIFY(scene() == before);
        QMessageBox *box = lessons()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->informativeText().startsWith(broken), qPrintable(box->informativeText()));
        box->close();

        const QString fifo = m_dir.filePath("scene.fifo");
        QCOMPARE(mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        QFile l(m_dir.filePath("steps.json"));
        QVERIFY(l.open(QIODevice::WriteOnly));
        l.write(R"({"format": "lightbench-lesson", "version": 1, "title": "Broken steps",
                   "steps": [{"title": "Fine", "scene": {"material": {"shininess": 9}}},
                             {"title": "Missing", "scene": "missing.json"},
                             {"title": "Pipe", "scene": "scene.fifo"}]})");
        l.close();
        QVERIFY(lessons()->open(l.fileName()));
        box = lessons()->messageBox();
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains("2 step(s) cannot be shown"), qPrintable(box->text()));
        QVERIFY2(box->informativeText().contains("missing.json") &&
                     box->informativeText().contains("scene.fifo"),
                 qPrintable(box->informativeText()));
        box->close();
        const Scene first = scene();
        for (int step : {1, 2}) {
            QVERIFY(lessons()->goTo(step));
            QVERIFY(scene() == first);
            const QString caption = lessons()->bar()->captionLabel()->text();
            QVERIFY2(caption.contains("cannot be shown") &&
                         caption.contains(step == 1 ? "missing.json" : "scene.fifo"),
                     qPrintable(caption));
        }
        QVERIFY(!lessons()->bar()->resetButton()->isEnabled());
    }

    // A teacher writes a lesson in the window: new, add, rename (the dialog), caption,
    // move, remove, save; it reads back as made. Bad titles and a failed save lose nothing.
    void authoringRoundTrips()
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 7; });
        lessons()->newLesson();
        QVERIFY(lessons()->isOpen() && lessons()->isModified());
        QVERIFY(lessons()->renameStep("Dull"));
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 70; });
        lessons()->addViewAsStep();
        QCOMPARE(lessons()->currentStep(), 1);
        // Rename through the menu's dialog, as a teacher would.
        QTimer::singleShot(0, this, [] {
            auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            dialog->setTextValue("Shiny");
            dialog->accept();
        });
        for (QAction *a : lessons()->lessonMenu()->actions())
            if (a->text() == tr("Rena&me Step..."))
                a->trigger();
        QCOMPARE(localized(lessons()->lesson().steps[1].title, "en"), QString("Shiny"));
        QVERIFY(lessons()->setCaption({{"en", "A *shiny* sphere"}, {"de", "Glänzend"}}));
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 300; });
        lessons()->addViewAsStep();
        QVERIFY(lessons()->renameStep("Mirror"));
        lessons()->moveStep(-1); // Dull, Mirror, Shiny
        QCOMPARE(lessons()->currentStep(), 1);
        // Bad input: an empty title, one too long, a caption too long: all refused.
        QVERIFY(!lessons()->renameStep("   "));
        QVERIFY(!lessons()->renameStep(QString(kMaxLessonTextCharacters + 1, 'x')));
        QVERIFY(!lessons()->setCaption({{"en", QString(kMaxLessonTextCharacters + 1, 'y')}}));
        QCOMPARE(localized(lessons()->lesson().steps[1].title, "en"), QString("Mirror"));
        // Four steps, then one removed again.
        lessons()->addViewAsStep();
        QCOMPARE(int(lessons()->lesson().steps.size()), 4);
        QVERIFY(lessons()->removeStep());
        QCOMPARE(int(lessons()->lesson().steps.size()), 3);

        // A save that fails (the target is a folder) keeps the lesson and its changes.
        QVERIFY(QDir(m_dir.path()).mkdir("folder.json"));
        QVERIFY(!lessons()->saveAs(m_dir.filePath("folder.json")));
        QVERIFY(lessons()->isModified());
        QVERIFY(lessons()->messageBox() && lessons()->messageBox()->isVisible());
        QVERIFY2(lessons()->messageBox()->informativeText().contains("folder.json"),
                 qPrintable(lessons()->messageBox()->informativeText()));
        QCOMPARE(int(lessons()->lesson().steps.size()), 3);

        const QString path = m_dir.filePath("written.json");
        QVERIFY(lessons()->saveAs(path));
        QVERIFY(!lessons()->isModified());
        const LessonRead read = readLessonFile(path);
        QVERIFY2(read.lesson, qPrintable(read.error));
        QVERIFY2(read.ignored.isEmpty() && read.stepErrors.isEmpty(),
                 qPrintable((read.ignored + read.stepErrors).join("; ")));
        const QStringList titles{"Dull", "Mirror", "Shiny"};
        const float shininess[] = {7, 300, 70};
        QCOMPARE(int(read.lesson->steps.size()), 3);
        for (int i = 0; i < 3; ++i) {
            const LessonStep &step = read.lesson->steps[std::size_t(i)];
            QCOMPARE(localized(step.title, "en"), titles[i]);
            QCOMPARE(step.scene.scene.objects[0].material.shininess, shininess[i]);
            QVERIFY(step.scene.scene == lessons()->lesson().steps[std::size_t(i)].scene.scene);
        }
        QCOMPARE(localized(read.lesson->steps[2].caption, "de"), QString("Glänzend"));
        QCOMPARE(localized(read.lesson->steps[2].caption, "pt"), QString("A *shiny* sphere"));
    }

    // The 501st step is refused when added (issue 49: it was added, saved with "Saved", and
    // the lesson could not be opened again); the 500 are saved and open again.
    void aLessonKeepsToTheStepsItMayHave()
    {
        lessons()->newLesson();
        while (int(lessons()->lesson().steps.size()) < kMaxLessonSteps)
            lessons()->addViewAsStep();
        lessons()->addViewAsStep();
        QCOMPARE(int(lessons()->lesson().steps.size()), kMaxLessonSteps);
        QVERIFY2(m_window->statusLine()->message().contains("at most 500 steps"),
                 qPrintable(m_window->statusLine()->message()));
        const QString path = m_dir.filePath("full.json");
        QVERIFY(lessons()->saveAs(path));
        const LessonRead read = readLessonFile(path);
        QVERIFY2(read.lesson, qPrintable(read.error));
        QCOMPARE(int(read.lesson->steps.size()), kMaxLessonSteps);
    }

    // The caption dialog: one field per language; too long is refused with a message.
    void theCaptionDialogKeepsOtherLanguages()
    {
        CaptionDialog dialog({{"en", "Hello"}, {"fr", "Bonjour"}}, "de", 10, m_window.get());
        QCOMPARE(dialog.tabs()->currentWidget(), dialog.field("de"));
        dialog.field("pt")->setPlainText("  Olá ");
        QCOMPARE(dialog.captions(),
                 (QMap<QString, QString>{{"en", "Hello"}, {"fr", "Bonjour"}, {"pt", "Olá"}}));
        dialog.field("en")->setPlainText("Far too long for ten");
        QTimer::singleShot(0, this, [] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget()))
                box->accept();
        });
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected)); // still open
        QCOMPARE(dialog.tabs()->currentWidget(), dialog.field("en"));
    }

    // Changes to the lesson are asked about before the window closes or the lesson does.
    void unsavedLessonChangesAreAskedAbout()
    {
        openFourSteps();
        QVERIFY(lessons()->renameStep("Renamed"));
        QStringList asked;
        m_window->setUnsavedWorkAsker([&](QWidget *, const QString &question, const QString &) {
            asked << question;
            return QMessageBox::Cancel;
        });
        QVERIFY(!lessons()->closeLesson());
        QVERIFY(lessons()->isOpen());
        // An example opened over the step, or Reset Everything, sets none of it aside.
        QVERIFY(m_window->sceneActions()->openAsking(":/examples/toon.json"));
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->text() == tr("Reset &Everything"))
                a->trigger();
        QVERIFY(lessons()->isOpen() && lessons()->isModified());
        QCOMPARE(asked.size(), 1);
        // Another lesson would set it aside: asked, and Cancel keeps this one.
        QVERIFY(!lessons()->openAsking(writeLesson(fourSteps(), "other.json")));
        QCOMPARE(asked.size(), 2);
        QVERIFY2(asked[1].contains("before opening \u201cother.json\u201d"), qPrintable(asked[1]));
        QCOMPARE(lessons()->name(), QString("lesson.json"));
        m_window->close();
        QVERIFY(m_window->isVisible());
        QCOMPARE(asked.size(), 3);
        QVERIFY2(asked[0].contains("the lesson \u201clesson.json\u201d"), qPrintable(asked[0]));
        QVERIFY(m_window->isWindowModified());
        m_window->setUnsavedWorkAsker(
            [](QWidget *, const QString &, const QString &) { return QMessageBox::Discard; });
        QVERIFY(lessons()->closeLesson());
        QVERIFY(!m_window->isWindowModified());
    }

    // A lesson file dropped on the window opens as a lesson, a scene file as a scene.
    void aDroppedLessonOpens()
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        const QString path = writeLesson(fourSteps());
        QVERIFY(LessonActions::isLessonFile(path));
        const QString fifo = m_dir.filePath("drop.fifo");
        QCOMPARE(mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        QVERIFY(!LessonActions::isLessonFile(fifo)); // not read: a FIFO would wait
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton,
                              Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &enter); // Qt delivers no drop without it
        QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &drop);
        QVERIFY(drop.isAccepted());
        QVERIFY(QTest::qWaitFor([this] { return lessons()->isOpen(); }, 2000));
        QVERIFY(scene() == stepScene(0));
        QCOMPARE(lessons()->recent()->files().first(), QFileInfo(path).absoluteFilePath());
    }

    // The lesson and step of the last session come back, with the session's scene as that
    // step's working copy; Reset Step brings the step as authored. A lesson gone since is not.
    void theLessonComesBackAtTheNextStart()
    {
        openFourSteps();
        QVERIFY(lessons()->goTo(2));
        m_window->document().edit([](Scene &s) { s.objects[0].material.shininess = 99; });
        const Scene edited = scene();
        m_window->close(); // saves the session
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        QVERIFY(lessons()->isOpen());
        QCOMPARE(lessons()->currentStep(), 2);
        QVERIFY(lessons()->bar()->isVisible());
        QVERIFY(scene() == edited);
        lessons()->resetStep();
        QVERIFY(scene() == stepScene(2));

        QVERIFY(QFile::remove(m_dir.filePath("lesson.json")));
        m_window->close();
        m_window = std::make_unique<MainWindow>(*m_settings);
        QVERIFY(!lessons()->isOpen());
        QVERIFY(!lessons()->bar()->isVisibleTo(m_window.get()));
    }

    // lightbench --lesson F --step 2 opens the window at step 2 (main's path): the session
    // it leaves behind holds step 2's scene.
    void theCommandLineOpensTheLessonAtItsStep()
    {
        const QString path = writeLesson(fourSteps());
        const LessonRead read = readLessonFile(path);
        QVERIFY(read.lesson);
        QTemporaryDir config;
        const QString png = config.filePath("shot.png");
        QCOMPARE(
            runLightbench({"--lesson", path, "--step", "2", "--screenshot", png}, config.path()),
            0); // -1: it waited
        QVERIFY(!QImage(png).isNull());
        QSettings session(config.filePath("lightbench/lightbench.conf"), QSettings::IniFormat);
        const Scene saved = Scene::fromJson(
            QJsonDocument::fromJson(session.value(window_settings::kSceneKey).toByteArray())
                .object());
        QVERIFY(saved == read.lesson->steps[1].scene.scene);
        QVERIFY(!(saved == read.lesson->steps[0].scene.scene));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowLessonFiles)

#include "test_window_lesson_files.moc"
