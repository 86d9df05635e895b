// Lessons in the window: opening, the lesson bar, stepping by keys, the step's scene, panel
// and highlight, the glide, edits kept per step, authoring and saving, broken lessons, and
// --lesson F --step N.
#include "window_fixture.h"

#include "caption_dialog.h"
#include "control_highlight.h"
#include "lesson.h"
#include "lesson_actions.h"
#include "lesson_bar.h"
#include "lesson_keys.h"
#include "lesson_motion.h"
#include "lesson_pointer.h"
#include "main_window_settings.h"

#include <QDockWidget>
#include <QDropEvent>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QTimer>
#include <QToolButton>
#include <QVariantAnimation>

#include <sys/stat.h>

using namespace lb;
using namespace lb::test;

namespace {

// Four steps that differ in shading, light, shininess and camera, so that each one shows.
Lesson fourSteps()
{
    Lesson lesson;
    lesson.title.insert("en", "Four steps");
    const Shading shadings[] = {Shading::Phong, Shading::Gouraud, Shading::Flat, Shading::Phong};
    for (int i = 0; i < 4; ++i) {
        LessonStep step;
        step.title.insert("en", QString("Title %1").arg(i + 1));
        step.caption.insert("en", QString("Caption **%1**").arg(i + 1));
        step.caption.insert("pt", QString("Legenda %1").arg(i + 1));
        Scene scene;
        scene.shading.shading = shadings[i];
        scene.lights[0].position = {0.5f * float(i), 2.0f, 1.0f + float(i), 1.0f};
        scene.objects[0].material.shininess = 5.0f + 20.0f * float(i);
        scene.camera.yawDegrees = 10.0f + 40.0f * float(i);
        step.scene = SceneFile{scene, std::nullopt, std::nullopt};
        if (i == 1) {
            step.panel = "material";
            step.highlight = "material.shininess";
        }
        lesson.steps.push_back(step);
    }
    return lesson;
}

} // namespace

class TestWindowLessons : public WindowTest
{
    Q_OBJECT

    LessonActions *lessons() { return m_window->lessonActions(); }
    // The scene step `index` has in the lesson as the window read it.
    const Scene &stepScene(int index)
    {
        return lessons()->lesson().steps[std::size_t(index)].scene.scene;
    }
    QString writeLesson(const Lesson &lesson, const QString &name = "lesson.json")
    {
        const QString path = m_dir.filePath(name);
        const QString error = writeLessonFile(path, lesson);
        return error.isEmpty() ? path : QString();
    }
    void openFourSteps(bool animate = false)
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, animate);
        const QString path = writeLesson(fourSteps());
        QVERIFY(!path.isEmpty());
        QVERIFY(lessons()->open(path));
        QVERIFY(lessons()->bar()->isVisible());
    }
    void press(Qt::Key key, QWidget *to = nullptr)
    {
        QTest::keyClick(to ? to : m_window.get(), key);
        QCoreApplication::processEvents();
    }

private slots:
    // Each of the clicker's and the keyboard's keys moves one step, and the scene is then
    // the step's: its shading, light, shininess and camera (which all differ).
    void keysStepThroughTheLesson()
    {
        openFourSteps();
        QCOMPARE(lessons()->currentStep(), 0);
        QVERIFY(scene() == stepScene(0));
        QVERIFY(!(stepScene(0) == stepScene(1)));
        const Qt::Key forward[] = {Qt::Key_PageDown, Qt::Key_Right, Qt::Key_Space};
        for (int i = 0; i < 3; ++i) {
            press(forward[i]);
            QCOMPARE(lessons()->currentStep(), i + 1);
            QVERIFY2(scene() == stepScene(i + 1), qPrintable(QString("step %1").arg(i + 2)));
        }
        QCOMPARE(lessons()->bar()->positionLabel()->text(), QString("Step 4 of 4"));
        QVERIFY(lessons()->bar()->titleLabel()->text().contains("Title 4"));
        press(Qt::Key_N); // the last step: nowhere to go
        QCOMPARE(lessons()->currentStep(), 3);
        const Qt::Key back[] = {Qt::Key_PageUp, Qt::Key_Left, Qt::Key_Backspace};
        for (int i = 0; i < 3; ++i) {
            press(back[i]);
            QCOMPARE(lessons()->currentStep(), 2 - i);
            QVERIFY(scene() == stepScene(2 - i));
        }
        press(Qt::Key_End);
        QCOMPARE(lessons()->currentStep(), 3);
        press(Qt::Key_P);
        QCOMPARE(lessons()->currentStep(), 2);
        press(Qt::Key_Home);
        QCOMPARE(lessons()->currentStep(), 0);
        press(Qt::Key_N);
        QCOMPARE(lessons()->currentStep(), 1);
        QVERIFY(scene() == stepScene(1));
        QVERIFY(m_window->windowTitle().startsWith("lesson.json, step 2"));
    }

    // Space, N and P are Auto-rotate, Show Normals and Perspective while no lesson is open;
    // with one open they take Shift, and the menus (which the F1 list is made from) say so.
    void theWindowsKeysMoveAsideAndComeBack()
    {
        auto find = [this](const QString &text) -> QAction * {
            for (QAction *a : m_window->findChildren<QAction *>())
                if (a->text() == text)
                    return a;
            return nullptr;
        };
        QAction *rotate = find(tr("&Auto-rotate"));
        QAction *normals = find(tr("Show &Normals"));
        QAction *projection = find(tr("Toggle &Perspective / Orthographic"));
        QVERIFY(rotate && normals && projection);
        QCOMPARE(rotate->shortcut(), QKeySequence("Space"));
        QVERIFY(lessons()->nextAction()->shortcuts().isEmpty());
        openFourSteps();
        QCOMPARE(rotate->shortcut(), QKeySequence("Shift+Space"));
        QCOMPARE(normals->shortcut(), QKeySequence("Shift+N"));
        QCOMPARE(projection->shortcut(), QKeySequence("Shift+P"));
        QVERIFY(lessons()->nextAction()->shortcuts().contains(QKeySequence("PgDown")));
        // The moved key works: Shift+P switches the projection, and does not step.
        const Projection before = scene().shading.projection;
        QTest::keyClick(m_window.get(), Qt::Key_P, Qt::ShiftModifier);
        QVERIFY(scene().shading.projection != before);
        QCOMPARE(lessons()->currentStep(), 0);
        QVERIFY(lessons()->closeLesson());
        QVERIFY(!lessons()->bar()->isVisible());
        QCOMPARE(rotate->shortcut(), QKeySequence("Space"));
        QCOMPARE(normals->shortcut(), QKeySequence("N"));
        QVERIFY(lessons()->nextAction()->shortcuts().isEmpty());
        const Projection now = scene().shading.projection;
        press(Qt::Key_P);
        QVERIFY(scene().shading.projection != now); // P is the projection's again
    }

    // Keys typed in the shader editor or a number box are the field's: they do not step.
    void keysInTextFieldsDoNotStep()
    {
        openFourSteps();
        QVERIFY(lessons()->goTo(1));
        m_window->editorDock()->show();
        m_window->editorDock()->raise();
        ShaderEditor *editor = m_window->editorPanel()->editor(ShaderStage::Fragment);
        if (!editor->isVisible())
            editor = m_window->editorPanel()->editor(ShaderStage::Vertex);
        QVERIFY(editor->isVisible());
        editor->setFocus();
        QVERIFY(QTest::qWaitFor([&] { return editor->hasFocus(); }, 2000));
        const QString text = editor->text();
        for (Qt::Key key : {Qt::Key_N, Qt::Key_P, Qt::Key_Space, Qt::Key_PageDown, Qt::Key_Right,
                            Qt::Key_Backspace, Qt::Key_Home})
            press(key, editor);
        QCOMPARE(lessons()->currentStep(), 1);
        QVERIFY(editor->text() != text); // the editor took them (n, p and a space typed)

        QDoubleSpinBox *box = m_window->lightPanel()->coordinate(0);
        for (QDockWidget *d : m_window->panelDocks())
            if (d->objectName() == "lightDock") {
                d->show();
                d->raise();
            }
        box->setFocus();
        QVERIFY(QTest::qWaitFor([&] { return box->hasFocus(); }, 2000));
        for (Qt::Key key : {Qt::Key_Right, Qt::Key_Left, Qt::Key_PageDown, Qt::Key_End})
            press(key, box);
        QCOMPARE(lessons()->currentStep(), 1);
    }

    // A moved light, a changed shininess and a typed shader stay with their step while the
    // class goes forward and back; Reset Step brings the step back as the lesson has it.
    void editsStayWithTheirStepUntilReset()
    {
        openFourSteps();
        QVERIFY(lessons()->goTo(1));
        m_window->document().edit([](Scene &s) {
            s.lights[0].position = {3.0f, -1.0f, 2.5f, 1.0f};
            s.objects[0].material.shininess = 111.0f;
        });
        ShaderEditor *editor = m_window->editorPanel()->editor(ShaderStage::Fragment);
        editor->setText(editor->text() + "\n// the class's note\n");
        QCoreApplication::processEvents();
        const Scene edited = scene();
        QVERIFY(!(edited == stepScene(1)));
        press(Qt::Key_PageDown);
        QVERIFY(scene() == stepScene(2));
        QVERIFY(!editor->text().contains("the class's note"));
        press(Qt::Key_PageUp);
        QCOMPARE(lessons()->currentStep(), 1);
        QVERIFY(scene() == edited);
        QVERIFY(editor->text().contains("the class's note"));
        lessons()->bar()->resetButton()->click();
        QVERIFY(scene() == stepScene(1));
        QVERIFY(!editor->text().contains("the class's note"));
        // The lesson itself did not change: nothing to ask about.
        QVERIFY(!lessons()->isModified());
        QVERIFY(!m_window->unsavedWork().any());
    }

    // The camera and the light glide to the step's places; the scene is the step's after.
    void stepsGlide()
    {
        openFourSteps(true);
        const float startYaw = scene().camera.yawDegrees;
        press(Qt::Key_PageDown);
        QVERIFY(lessons()->motion()->isRunning());
        QVERIFY(scene().camera.yawDegrees != stepScene(1).camera.yawDegrees);
        QVERIFY(QTest::qWaitFor([&] { return scene().camera.yawDegrees != startYaw; }, 2000));
        QVERIFY(QTest::qWaitFor([&] { return !lessons()->motion()->isRunning(); }, 3000));
        QVERIFY(scene() == stepScene(1));
        // Off in the preferences: the step is there at once.
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        press(Qt::Key_PageDown);
        QVERIFY(!lessons()->motion()->isRunning());
        QVERIFY(scene() == stepScene(2));
    }

    // The step's panel comes forward and its control is framed for a moment.
    void aStepPointsAtItsControl()
    {
        openFourSteps();
        QDockWidget *materialDock = nullptr;
        for (QDockWidget *d : m_window->panelDocks())
            if (d->objectName() == "materialDock")
                materialDock = d;
        QVERIFY(materialDock);
        materialDock->hide();
        QVERIFY(!ControlHighlight::current());
        press(Qt::Key_PageDown);
        QVERIFY(QTest::qWaitFor([&] { return materialDock->isVisible(); }, 2000));
        QVERIFY(QTest::qWaitFor([] { return ControlHighlight::current() != nullptr; }, 2000));
        QWidget *box = m_window->materialPanel()->shininessBox();
        const QRect boxArea(box->mapTo(m_window.get(), QPoint(0, 0)), box->size());
        QVERIFY(ControlHighlight::current()->geometry().contains(boxArea));
        QVERIFY(QTest::qWaitFor([] { return ControlHighlight::current() == nullptr; }, 4000));
        // Every control a lesson may name is one in the window.
        for (const QString &name : lessonHighlights())
            QVERIFY2(!lessonHighlightControls(*m_window, name).empty(), qPrintable(name));
        QVERIFY(lessonHighlightControls(*m_window, "no.such.control").empty());
    }

    // A caption is markdown; its pictures and HTML are left out: a caption naming a FIFO or
    // /dev/zero as a picture must not make the window read it.
    void captionsShowMarkdownButReadNoFiles()
    {
        const QString fifo = m_dir.filePath("picture.fifo");
        QCOMPARE(mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        Lesson lesson = fourSteps();
        lesson.steps[0].caption = {{"en", QString("The **diffuse** term ![x](%1) "
                                                  "<img src=\"/dev/zero\"> ![y](/dev/zero)")
                                              .arg(fifo)}};
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        QVERIFY(lessons()->open(writeLesson(lesson)));
        const QString shown = lessons()->bar()->captionLabel()->text();
        QVERIFY2(shown.contains("diffuse") && shown.contains("font-weight"), qPrintable(shown));
        QVERIFY2(!shown.contains("<img"), qPrintable(shown));
        QTest::qWait(50); // laid out and painted, with nothing to read
        QVERIFY(lessons()->bar()->captionLabel()->isVisible());
    }

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
        m_window->close();
        QVERIFY(m_window->isVisible());
        QCOMPARE(asked.size(), 2);
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

    // lightbench --lesson F --step 2 opens the window at step 2 (main's path): the session
    // it leaves behind holds step 2's scene.
    void theCommandLineOpensTheLessonAtItsStep()
    {
        const QString path = writeLesson(fourSteps());
        const LessonRead read = readLessonFile(path);
        QVERIFY(read.lesson);
        QTemporaryDir config;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("XDG_CONFIG_HOME", config.path());
        QProcess run;
        run.setProcessEnvironment(env);
        const QString png = config.filePath("shot.png");
        run.start(LIGHTBENCH_EXE, {"--lesson", path, "--step", "2", "--screenshot", png});
        const bool finished = run.waitForFinished(60000);
        if (!finished) {
            run.kill();
            run.waitForFinished();
        }
        QVERIFY2(finished, "the run waited");
        QCOMPARE(run.exitCode(), 0);
        QVERIFY(!QImage(png).isNull());
        QSettings session(config.filePath("lightbench/lightbench.conf"), QSettings::IniFormat);
        const Scene saved = Scene::fromJson(
            QJsonDocument::fromJson(session.value(window_settings::kSceneKey).toByteArray())
                .object());
        QVERIFY(saved == read.lesson->steps[1].scene.scene);
        QVERIFY(!(saved == read.lesson->steps[0].scene.scene));
    }
};

LB_WINDOW_TEST_MAIN(TestWindowLessons)

#include "test_window_lessons.moc"
