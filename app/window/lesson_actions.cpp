#include "lesson_actions.h"

#include "control_highlight.h"
#include "lesson_bar.h"
#include "lesson_keys.h"
#include "lesson_motion.h"
#include "lesson_pointer.h"
#include "main_window.h"
#include "main_window_settings.h"
#include "message_box.h"
#include "message_text.h"
#include "recent_files.h"
#include "scene_actions.h"
#include "status_line.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QTimer>

#include <algorithm>

namespace lb {

namespace {
const char *kRecentLessonsKey = "recentLessons";
const char *kCurrentLessonKey = "lessons/current"; // the lesson open at the end of the session
const char *kStepKey = "lessons/step";             // its step, from 1
const char *kLanguageKey = "lessons/language";     // captions' language; empty: the system's
} // namespace

LessonActions::LessonActions(MainWindow *window, LessonBar *bar, QSettings &settings)
    : QObject(window), m_window(window), m_bar(bar), m_settings(settings)
{
    m_motion = new LessonMotion(&window->document(), this);
    m_recent = new RecentFiles(tr("Open Recent &Lesson"), settings, kRecentLessonsKey, window);
    connect(m_recent, &RecentFiles::fileChosen, this,
            [this](const QString &path) { openAsking(path); });
    buildLessonMenu();
    m_keys = new LessonKeys(window, m_nextAction, m_previousAction, m_firstAction, m_lastAction);
    m_bar->setMenu(m_menu);
    m_bar->hide();
    connect(m_bar, &LessonBar::nextRequested, this, &LessonActions::next);
    connect(m_bar, &LessonBar::previousRequested, this, &LessonActions::previous);
    connect(m_bar, &LessonBar::resetRequested, this, &LessonActions::resetStep);
    connect(m_bar, &LessonBar::closeRequested, this, &LessonActions::closeLesson);
    // A scene the user opens takes the view over: a glide under way must not pull it back.
    connect(window->sceneActions(), &SceneActions::sceneOpened, this,
            [this](const QString &origin) {
                if (!origin.isEmpty())
                    m_motion->stop(false);
            });
    updateActions();
    connect(this, &LessonActions::changed, this, &LessonActions::remember);
}

void LessonActions::remember()
{
    // A new lesson not yet saved has no file to come back from.
    m_settings.setValue(kCurrentLessonKey, m_open ? m_path : QString());
    m_settings.setValue(kStepKey, m_current + 1);
}

void LessonActions::restoreSession()
{
    const QString path = m_settings.value(kCurrentLessonKey).toString();
    if (path.isEmpty())
        return;
    const LessonRead read = readLessonFile(path);
    if (!read.lesson) {
        m_settings.remove(kCurrentLessonKey);
        showStatusMessage(m_window,
                          tr("The last lesson could not be opened again: %1").arg(read.error));
        return;
    }
    m_lesson = *read.lesson;
    m_path = path;
    m_working.assign(m_lesson.steps.size(), std::nullopt);
    m_current =
        std::clamp(m_settings.value(kStepKey, 1).toInt() - 1, 0, int(m_lesson.steps.size()) - 1);
    m_modified = false;
    // The scene the session kept is this step as the class left it (Reset Step: as authored).
    const LessonStep &step = m_lesson.steps[std::size_t(m_current)];
    m_shown = step.error.isEmpty();
    if (m_shown) {
        // An exercise step comes back whole: the student's edit with the step's exercise (the
        // session keeps the scene and program, not the exercise: without it the Exercise tab
        // was gone and Check My Work greyed until Reset Step threw the edit away).
        if (step.scene.exercise)
            m_window->sceneActions()->restoreExercise(step.scene);
        m_working[std::size_t(m_current)] = currentView();
    }
    setOpen(true);
    showStep();
    emit changed();
}

void LessonActions::addToMenu(QMenu *file)
{
    file->addAction(tr("Open &Lesson..."), this, &LessonActions::showOpenDialog);
    QMenu *shipped = file->addMenu(tr("Lesso&ns"));
    // The lessons that ship are read when the menu opens, titled as they title themselves.
    connect(shipped, &QMenu::aboutToShow, this, [this, shipped] {
        shipped->clear();
        for (const auto &[title, resource] : shippedLessons())
            shipped->addAction(title, this, [this, resource = resource] { openAsking(resource); });
        if (shipped->isEmpty())
            shipped->addAction(tr("(none built in)"))->setEnabled(false);
    });
    file->addMenu(m_recent);
}

void LessonActions::buildLessonMenu()
{
    m_menu = new QMenu(tr("Less&on"), m_window);
    m_menu->setObjectName("lessonMenu");
    auto add = [this](const QString &text, auto slot, bool needsLesson = true) {
        QAction *action = m_menu->addAction(text, this, slot);
        if (needsLesson)
            m_needsLesson << action;
        return action;
    };
    // Their keys are set while a lesson is open (lesson_keys.h), so that closed, the keys
    // are the window's again.
    m_nextAction = add(tr("&Next Step"), [this] { next(); });
    m_previousAction = add(tr("&Previous Step"), [this] { previous(); });
    m_firstAction = add(tr("&First Step"), [this] { goTo(0); });
    m_lastAction = add(tr("&Last Step"), [this] { goTo(int(m_lesson.steps.size()) - 1); });
    add(tr("&Reset Step"), [this] { resetStep(); });
    m_menu->addSeparator();
    add(
        tr("New Lesson from This &View"), [this] { newLesson(); }, false);
    add(
        tr("&Add This View as a Step"), [this] { addViewAsStep(); }, false);
    add(tr("Replace the Step with &This View"), [this] { replaceStepWithView(); });
    add(tr("Rena&me Step..."), [this] { showRenameDialog(); });
    add(tr("Edit &Caption..."), [this] { showCaptionDialog(); });
    add(tr("Move Step &Up"), [this] { moveStep(-1); });
    add(tr("Move Step &Down"), [this] { moveStep(+1); });
    m_removeAction = add(tr("Remo&ve Step"), [this] { removeStep(); });
    m_menu->addSeparator();
    add(tr("&Save Lesson"), [this] { save(); });
    add(tr("Save Lesson &As..."), [this] { showSaveAsDialog(); });
    m_menu->addSeparator();
    addLanguageMenu();
    m_menu->addSeparator();
    add(tr("&Close Lesson"), [this] { closeLesson(); });
}

void LessonActions::addLanguageMenu()
{
    // The captions (and the examples' exercise) follow the window's language (View >
    // Language) or the one chosen here: a teacher shows the German sheet in English.
    QMenu *menu = m_menu->addMenu(tr("Caption &Language"));
    auto *group = new QActionGroup(menu);
    const QString chosen = m_settings.value(kLanguageKey).toString();
    // Each language named in itself (as language menus do), so it is found whatever the
    // window speaks: not translated.
    const std::pair<QString, QString> languages[] = {
        //: Lesson > Caption Language: the same language as the window's menus (View > Language)
        {QString(), tr("Same as the Window")},
        {"en", "English"},
        {"pt", "Português"},
        {"de", "Deutsch"}};
    for (const auto &[code, name] : languages) {
        QAction *action = menu->addAction(name, this, [this, code = code] {
            m_settings.setValue(kLanguageKey, code);
            setLessonLanguage(code);
            if (m_open)
                showStep();
        });
        action->setCheckable(true);
        action->setChecked(code == chosen);
        action->setData(code);
        group->addAction(action);
    }
    setLessonLanguage(chosen);
}

void LessonActions::updateActions()
{
    for (QAction *action : m_needsLesson)
        action->setEnabled(m_open);
    m_removeAction->setEnabled(m_open && m_lesson.steps.size() > 1);
}

QList<QPair<QString, QString>> LessonActions::shippedLessons()
{
    QList<QPair<QString, QString>> lessons;
    const QDir dir(":/lessons");
    for (const QString &file : dir.entryList({"*.json"}, QDir::Files, QDir::Name)) {
        const QString resource = dir.filePath(file);
        const LessonRead read = readLessonFile(resource);
        QString title = read.lesson ? localized(read.lesson->title, lessonLanguage()) : QString();
        lessons.append({title.isEmpty() ? file : title, resource});
    }
    return lessons;
}

bool LessonActions::isLessonFile(const QString &path)
{
    // Only a regular file is looked into (a FIFO would keep the drop waiting), and only its
    // beginning: "format" comes first in the files we write.
    if (!QFileInfo(path).isFile())
        return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    static const QRegularExpression format(R"("format"\s*:\s*"lightbench-lesson")");
    return format.match(QString::fromUtf8(file.read(4096))).hasMatch();
}

QString LessonActions::name() const
{
    return m_path.isEmpty() ? tr("untitled lesson") : QFileInfo(m_path).fileName();
}

bool LessonActions::openAsking(const QString &path, int step)
{
    const bool openable = path.startsWith(":/") || QFileInfo(path).isFile();
    if (openable && m_maySetAside &&
        !m_maySetAside(SetAsideFor::OpeningLesson, QFileInfo(path).fileName()))
        return false;
    return open(path, step);
}

bool LessonActions::open(const QString &path, int step)
{
    const bool resource = path.startsWith(":/");
    const LessonRead read = readLessonFile(path);
    if (!read.lesson) {
        showMessage(QMessageBox::Warning, tr("The lesson could not be opened; nothing changed."),
                    read.error);
        if (!resource && !QFileInfo::exists(path))
            m_recent->remove(path);
        return false;
    }
    m_motion->stop(true);
    const Scene before = m_window->document().scene();
    m_lesson = *read.lesson;
    m_path = resource ? path : QFileInfo(path).absoluteFilePath();
    m_working.assign(m_lesson.steps.size(), std::nullopt);
    m_current = std::clamp(step, 0, int(m_lesson.steps.size()) - 1);
    m_modified = false;
    setOpen(true);
    applyStep(before);
    if (!resource)
        m_recent->add(m_path);
    // What could not be used, once for the whole lesson (as a scene's ignored fields are).
    QStringList notes = read.stepErrors;
    notes << read.ignored;
    if (!read.stepErrors.isEmpty())
        showMessage(QMessageBox::Warning,
                    tr("%1 opened; %n step(s) cannot be shown (the lesson bar says why there).", "",
                       int(read.stepErrors.size()))
                        .arg(escapedName(name())),
                    summarisedList(notes, "\n", 20));
    else if (!read.ignored.isEmpty())
        showMessage(QMessageBox::Information,
                    tr("%1 opened; %n field(s) could not be used and kept their defaults.", "",
                       int(read.ignored.size()))
                        .arg(escapedName(name())),
                    summarisedList(notes, "\n", 20));
    return true;
}

bool LessonActions::closeLesson()
{
    if (!m_open)
        return false;
    if (m_modified && m_maySetAside && !m_maySetAside(SetAsideFor::ClosingLesson, name()))
        return false;
    m_motion->stop(true);
    m_lesson = Lesson{};
    m_working.clear();
    m_path.clear();
    m_modified = false;
    m_current = 0;
    setOpen(false);
    emit changed();
    return true;
}

void LessonActions::setOpen(bool open)
{
    m_open = open;
    m_bar->setVisible(open);
    m_keys->setActive(open);
    updateActions();
}

SceneFile LessonActions::stepScene(int index) const
{
    const std::size_t i = std::size_t(index);
    return m_working[i] ? *m_working[i] : m_lesson.steps[i].scene;
}

SceneFile LessonActions::currentView()
{
    return SceneFile{m_window->document().scene(), m_window->shaderDocument().program(),
                     m_window->sceneActions()->exercise()};
}

void LessonActions::keepWorkingCopy()
{
    m_motion->stop(true); // not halfway
    if (m_open && m_shown)
        m_working[std::size_t(m_current)] = currentView();
}

bool LessonActions::goTo(int index)
{
    if (!m_open)
        return false;
    index = std::clamp(index, 0, int(m_lesson.steps.size()) - 1);
    if (index == m_current)
        return false;
    keepWorkingCopy();
    const Scene before = m_window->document().scene();
    m_current = index;
    applyStep(before);
    return true;
}

void LessonActions::resetStep()
{
    if (!m_open)
        return;
    m_motion->stop(true);
    const Scene before = m_window->document().scene();
    m_working[std::size_t(m_current)].reset();
    applyStep(before);
}

void LessonActions::applyStep(const Scene &before)
{
    const LessonStep &step = m_lesson.steps[std::size_t(m_current)];
    m_shown = step.error.isEmpty();
    if (m_shown) {
        // As opening that scene file would: the scene, its program and its exercise; what
        // it ignored was said once when the lesson opened.
        m_window->sceneActions()->apply(stepScene(m_current), {}, {});
        if (m_settings.value(window_settings::kAnimateLessonsKey, true).toBool() &&
            m_window->isVisible())
            m_motion->start(before);
        pointAtStep();
    }
    showStep();
    emit changed();
}

void LessonActions::pointAtStep()
{
    // Once the window has arranged its docks (a lesson opened before the window shows, from
    // the command line, would have its dock put back behind another) and laid them out.
    const LessonStep &step = m_lesson.steps[std::size_t(m_current)];
    QTimer::singleShot(0, this, [this, panel = step.panel, highlight = step.highlight] {
        for (const QString &name : {panel, lessonHighlightPanel(highlight)})
            m_window->bringForward(lessonPanelDock(*m_window, name));
        // Its controls have their places once the dock is up; none while the panels wait
        // behind F6 in presentation mode.
        if (!highlight.isEmpty() && !m_window->panelsWaitBehindF6())
            QTimer::singleShot(0, this, [this, highlight] {
                ControlHighlight::frame(lessonHighlightControls(*m_window, highlight));
            });
    });
}

void LessonActions::showStep()
{
    const LessonStep &step = m_lesson.steps[std::size_t(m_current)];
    const QString language = lessonLanguage();
    QString title = localized(step.title, language);
    if (title.isEmpty())
        title = tr("Step %1").arg(m_current + 1);
    m_bar->showStep(m_current, int(m_lesson.steps.size()), title,
                    withControlNames(*m_window, localized(step.caption, language)), step.error);
    updateActions();
}

void LessonActions::markModified()
{
    m_modified = true;
    showStep();
    emit changed();
}

void LessonActions::showOpenDialog()
{
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Open a lesson"), m_settings.value(kDirKey).toString(),
        tr("Lessons (*.lblesson *.json);;All files (*)"));
    if (path.isEmpty())
        return;
    m_settings.setValue(kDirKey, QFileInfo(path).absolutePath());
    openAsking(path);
}

void LessonActions::showMessage(QMessageBox::Icon icon, const QString &text, const QString &details)
{
    showFileMessage(m_messageBox, m_window, icon, tr("Lesson"), text, details);
}

} // namespace lb
