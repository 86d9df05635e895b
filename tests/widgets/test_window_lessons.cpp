// Lessons in the window: the lesson bar, stepping by keys (and text fields keeping theirs),
// the step's scene, panel and highlight, the glide, and edits kept per step.
#include "lesson_fixture.h"

using namespace lb;
using namespace lb::test;

class TestWindowLessons : public LessonWindowTest
{
    Q_OBJECT
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
        // The F1 list is made from the menus: it names the keys that work now.
        const QString keys = shortcutsHtml(m_window->menuBar());
        QVERIFY2(keys.contains("Shift+Space") && keys.contains("PgDown"), qPrintable(keys));
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
        QVERIFY(!shortcutsHtml(m_window->menuBar()).contains("Shift+Space"));
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

    // An exercise step of the shipped exercise sheet, edited, comes back whole in the next
    // session: the edit, the Exercise tab and Check My Work (F9); before, the tab was gone and
    // F9 greyed until Reset Step threw the edit away (issue 49, item 12).
    void anExerciseStepComesBackWhole()
    {
        m_settings->setValue(window_settings::kAnimateLessonsKey, false);
        QVERIFY(lessons()->open(":/lessons/exercise_sheet.json"));
        int exerciseStep = -1;
        for (int i = 0; i < int(lessons()->lesson().steps.size()) && exerciseStep < 0; ++i)
            if (lessons()->lesson().steps[std::size_t(i)].scene.exercise)
                exerciseStep = i;
        QVERIFY(exerciseStep > 0);
        QVERIFY(lessons()->goTo(exerciseStep));
        QTRY_VERIFY(m_window->exerciseDock()->isVisible());
        auto checkAction = [this] {
            for (QAction *a : m_window->findChildren<QAction *>())
                if (a->text() == "Chec&k My Work")
                    return a;
            return static_cast<QAction *>(nullptr);
        };
        QVERIFY(checkAction() && checkAction()->isEnabled());
        ShaderEditor *editor = m_window->editorPanel()->editor(ShaderStage::Fragment);
        editor->setText(editor->text() + "\n// the student's answer\n");
        QCoreApplication::processEvents();

        m_window->close(); // saves the session
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        QVERIFY(lessons()->isOpen());
        QCOMPARE(lessons()->currentStep(), exerciseStep);
        editor = m_window->editorPanel()->editor(ShaderStage::Fragment);
        QVERIFY(editor->text().contains("the student's answer"));
        QTRY_VERIFY(m_window->exerciseDock()->isVisible());
        QVERIFY(m_window->sceneActions()->exercise().has_value());
        QVERIFY(checkAction() && checkAction()->isEnabled());
        // Away and back: the working copy keeps the exercise too.
        QVERIFY(lessons()->goTo(exerciseStep - 1));
        QVERIFY(lessons()->goTo(exerciseStep));
        QVERIFY(editor->text().contains("the student's answer"));
        QVERIFY(m_window->sceneActions()->exercise().has_value());
        QVERIFY(checkAction()->isEnabled());
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
        // Off in Edit > Preferences: the step is there at once.
        QTimer::singleShot(0, this, [] {
            auto *dialog = qobject_cast<PreferencesDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            QVERIFY(dialog->animateLessonsCheck()->isChecked());
            dialog->animateLessonsCheck()->setChecked(false);
            dialog->accept();
        });
        m_window->meshActions()->showPreferences();
        QCOMPARE(m_settings->value(window_settings::kAnimateLessonsKey).toBool(), false);
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
    // The captions' language is chosen in the Lesson menu and kept; a step without that
    // language shows English.
    void theCaptionLanguageIsChosenAndKept()
    {
        openFourSteps();
        // The menu of the window there is now (a new one below).
        const auto choose = [&](const QString &name) {
            int chosen = 0;
            for (QAction *a : lessons()->lessonMenu()->actions())
                if (a->menu() && a->text().contains("Language"))
                    for (QAction *l : a->menu()->actions())
                        if (l->text() == name)
                            l->trigger(), ++chosen;
            QCOMPARE(chosen, 1);
        };
        choose("Português");
        QVERIFY(lessons()->bar()->captionLabel()->text().contains("Legenda 1"));
        choose("Deutsch"); // the lesson has none: English
        QVERIFY2(lessons()->bar()->captionLabel()->text().contains("Caption"),
                 qPrintable(lessons()->bar()->captionLabel()->text()));
        choose("Português");
        // A new window on the same settings shows Portuguese again.
        m_window->close(); // saves the session
        setLessonLanguage({});
        m_window = std::make_unique<MainWindow>(*m_settings);
        m_window->show();
        QVERIFY(lessons()->isOpen()); // the lesson of the last session came back
        QVERIFY(lessons()->bar()->captionLabel()->text().contains("Legenda 1"));
        // "Same as the Window": the captions follow View > Language (here Portuguese).
        setDefaultLessonLanguage("pt");
        choose("Deutsch");
        choose("Same as the Window");
        QVERIFY(lessons()->bar()->captionLabel()->text().contains("Legenda 1"));
        setDefaultLessonLanguage({});
    }

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
};

LB_WINDOW_TEST_MAIN(TestWindowLessons)

#include "test_window_lessons.moc"
