#pragma once
// What the lesson tests share: a lesson of four steps that differ, written to the test's
// folder, and the window's lesson driven by keys.
#include "window_fixture.h"

#include "caption_dialog.h"
#include "control_highlight.h"
#include "help.h"
#include "lesson.h"
#include "lesson_actions.h"
#include "lesson_bar.h"
#include "lesson_keys.h"
#include "lesson_motion.h"
#include "lesson_pointer.h"
#include "main_window_settings.h"
#include "preferences_dialog.h"

#include <QCheckBox>
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

namespace lb::test {

// Four steps that differ in shading, light, shininess and camera, so that each one shows.
inline Lesson fourSteps()
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

class LessonWindowTest : public WindowTest
{
protected:
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
};

} // namespace lb::test
