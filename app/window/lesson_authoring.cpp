// LessonActions: a lesson written in the window (the Lesson menu), so a teacher never edits
// JSON by hand. Each change marks the lesson changed; Save writes the lesson as authored
// (not the class's edits to its steps), and a failed save loses nothing.
#include "lesson_actions.h"

#include "caption_dialog.h"
#include "lesson_bar.h"
#include "lesson_motion.h"
#include "main_window.h"
#include "recent_files.h"
#include "status_line.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLineEdit>
#include <QSettings>

#include <algorithm>

namespace lb {

void LessonActions::newLesson()
{
    if (m_open && m_modified && m_maySetAside && !m_maySetAside(SetAsideFor::NewLesson, {}))
        return;
    m_motion->stop(true);
    Lesson lesson;
    // The first title and step titles are the teacher's to change: written into the lesson
    // file as its text (in the captions' language), not read back as keys.
    //: a new lesson's title, until the teacher renames it (saved in the lesson file)
    lesson.title.insert(lessonLanguage(), tr("Lesson"));
    LessonStep first;
    //: a new step's title, until the teacher renames it (saved in the lesson file)
    first.title.insert(lessonLanguage(), tr("Step %1").arg(1));
    first.scene = currentView();
    first.scene.exercise.reset(); // the view: its scene and program
    lesson.steps.push_back(first);
    m_lesson = lesson;
    m_working.assign(1, std::nullopt);
    m_current = 0;
    m_path.clear();
    m_shown = true; // the view is the step already
    setOpen(true);
    markModified();
}

void LessonActions::addViewAsStep()
{
    if (!m_open) {
        newLesson();
        return;
    }
    // The reader opens at most kMaxLessonSteps: a step past them would be saved ("Saved")
    // into a lesson that cannot be opened again.
    if (int(m_lesson.steps.size()) >= kMaxLessonSteps) {
        showStatusMessage(m_window,
                          tr("A lesson has at most %1 steps and this one has them all: the view "
                             "was not added")
                              .arg(kMaxLessonSteps),
                          10000);
        return;
    }
    keepWorkingCopy();
    LessonStep step;
    step.scene = currentView();
    step.scene.exercise.reset();
    const int at = m_current + 1;
    step.title.insert(lessonLanguage(), tr("Step %1").arg(at + 1));
    m_lesson.steps.insert(m_lesson.steps.begin() + at, step);
    m_working.insert(m_working.begin() + at, std::nullopt);
    m_current = at;
    m_shown = true;
    markModified();
}

void LessonActions::replaceStepWithView()
{
    if (!m_open)
        return;
    m_motion->stop(true);
    LessonStep &step = m_lesson.steps[std::size_t(m_current)];
    step.scene = currentView();
    step.scene.exercise.reset();
    step.scenePath.clear(); // inline from now on
    step.error.clear();
    m_working[std::size_t(m_current)].reset();
    m_shown = true;
    markModified();
}

bool LessonActions::renameStep(const QString &title)
{
    if (!m_open)
        return false;
    const QString text = title.trimmed();
    if (text.isEmpty() || text.size() > kMaxLessonTextCharacters) {
        showMessage(QMessageBox::Warning, tr("The step keeps its title."),
                    text.isEmpty() ? tr("A step's title cannot be empty.")
                                   : tr("The title has %1 characters; a title holds at most %2.")
                                         .arg(text.size())
                                         .arg(kMaxLessonTextCharacters));
        return false;
    }
    m_lesson.steps[std::size_t(m_current)].title.insert(lessonLanguage(), text);
    markModified();
    return true;
}

bool LessonActions::setCaption(const LocalizedText &caption)
{
    if (!m_open)
        return false;
    for (auto it = caption.begin(); it != caption.end(); ++it)
        if (it.value().size() > kMaxLessonTextCharacters) {
            showMessage(QMessageBox::Warning, tr("The step keeps its caption."),
                        //: %1: the caption's language code (en, de, pt)
                        tr("The %1 caption has %2 characters; a caption holds at most %3.")
                            .arg(it.key(), QString::number(it.value().size()),
                                 QString::number(kMaxLessonTextCharacters)));
            return false;
        }
    m_lesson.steps[std::size_t(m_current)].caption = caption;
    markModified();
    return true;
}

void LessonActions::moveStep(int delta)
{
    const int to = m_current + delta;
    if (!m_open || to < 0 || to >= int(m_lesson.steps.size()))
        return;
    std::swap(m_lesson.steps[std::size_t(m_current)], m_lesson.steps[std::size_t(to)]);
    std::swap(m_working[std::size_t(m_current)], m_working[std::size_t(to)]);
    m_current = to; // the step moves; the view stays on it
    markModified();
}

bool LessonActions::removeStep()
{
    if (!m_open)
        return false;
    if (m_lesson.steps.size() <= 1) {
        showMessage(QMessageBox::Information, tr("The step stays."),
                    tr("A lesson keeps at least one step; Close Lesson puts it away."));
        return false;
    }
    m_motion->stop(true);
    const Scene before = m_window->document().scene();
    m_lesson.steps.erase(m_lesson.steps.begin() + m_current);
    m_working.erase(m_working.begin() + m_current);
    m_current = std::min(m_current, int(m_lesson.steps.size()) - 1);
    m_modified = true;
    applyStep(before); // the step now in its place
    return true;
}

bool LessonActions::save()
{
    if (!m_open)
        return false;
    if (m_path.isEmpty() || m_path.startsWith(":/")) { // a new or a built-in lesson
        showSaveAsDialog();
        return !m_modified;
    }
    return saveAs(m_path);
}

bool LessonActions::saveAs(const QString &path)
{
    if (!m_open)
        return false;
    const QString error = writeLessonFile(path, m_lesson);
    if (!error.isEmpty()) {
        showMessage(QMessageBox::Warning,
                    tr("The lesson was not saved; it stays open with its changes."), error);
        return false;
    }
    m_path = QFileInfo(path).absoluteFilePath();
    m_modified = false;
    m_recent->add(m_path);
    showStatusMessage(m_window, tr("Saved the lesson to %1").arg(path), 5000);
    emit changed();
    return true;
}

void LessonActions::showSaveAsDialog()
{
    const QString start =
        m_path.isEmpty() || m_path.startsWith(":/") ? m_settings.value(kDirKey).toString() : m_path;
    // .json first, the course's format: a name typed without an ending gets .json unless the
    // .lblesson filter (the desktop's type for lessons) is chosen, or the lesson's file has it.
    const QString json = tr("Lessons (*.json)"), lblesson = tr("lightbench lessons (*.lblesson)");
    QString chosenFilter = m_path.endsWith(".lblesson", Qt::CaseInsensitive) ? lblesson : json;
    QString path = QFileDialog::getSaveFileName(m_window, tr("Save the lesson"), start,
                                                json + ";;" + lblesson + ";;" + tr("All files (*)"),
                                                &chosenFilter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += chosenFilter == lblesson ? ".lblesson" : ".json";
    m_settings.setValue(kDirKey, QFileInfo(path).absolutePath());
    saveAs(path);
}

void LessonActions::showRenameDialog()
{
    if (!m_open)
        return;
    bool ok = false;
    const QString title = QInputDialog::getText(
        m_window, tr("Rename Step"), tr("The title of step %1:").arg(m_current + 1),
        QLineEdit::Normal,
        localized(m_lesson.steps[std::size_t(m_current)].title, lessonLanguage()), &ok);
    if (ok)
        renameStep(title);
}

void LessonActions::showCaptionDialog()
{
    if (!m_open)
        return;
    CaptionDialog dialog(m_lesson.steps[std::size_t(m_current)].caption, lessonLanguage(),
                         kMaxLessonTextCharacters, m_window);
    if (dialog.exec() == QDialog::Accepted)
        setCaption(dialog.captions());
}

} // namespace lb
