#pragma once
// The window's lessons: File > Open Lesson, File > Lessons (the shipped ones), Open Recent
// Lesson and a dropped lesson file; the lesson bar under the view; stepping (lesson_keys.h);
// and authoring in the window (the Lesson menu: lesson_authoring.cpp). A step's scene is
// applied as opening that scene file would (SceneActions::apply), its panel brought forward
// and its control pointed at; the camera and the lights glide there (lesson_motion.h).
//
// While a lesson is open, each step keeps the class's edits (a moved light, a typed shader)
// as its working copy until Reset Step or the lesson closes; the lesson as authored is what
// Save writes, and its changes are what closing asks about.

#include "lesson.h"
#include "unsaved_work.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>
#include <vector>

class QAction;
class QMenu;
class QSettings;

namespace lb {

class LessonBar;
class LessonKeys;
class LessonMotion;
class MainWindow;
class RecentFiles;

class LessonActions : public QObject
{
    Q_OBJECT
public:
    // `bar`: the window's lesson bar (hidden while no lesson is open).
    LessonActions(MainWindow *window, LessonBar *bar, QSettings &settings);

    // File > Open Lesson..., New Lesson, Lessons, Open Recent Lesson; and the Lesson menu
    // (stepping and authoring), which the window puts in its menu bar.
    void addToMenu(QMenu *file);
    QMenu *lessonMenu() const { return m_menu; }

    // Opens the lesson at `path` at step `step` (from 0): a lesson that cannot be read
    // changes nothing and says why (false); what was ignored and the broken steps are said
    // once.
    bool open(const QString &path, int step = 0);
    // The user's open: asks about unsaved work first (setMaySetAside), then open().
    bool openAsking(const QString &path, int step = 0);
    void setMaySetAside(std::function<bool(SetAsideFor, const QString &target)> ask)
    {
        m_maySetAside = std::move(ask);
    }
    // Closes the lesson (asking about its unsaved changes); the scene stays as it is.
    bool closeLesson();
    bool isOpen() const { return m_open; }
    const Lesson &lesson() const { return m_lesson; }
    QString path() const { return m_path; } // empty for a new lesson not yet saved
    QString name() const;                   // its file's name, or "untitled lesson"
    int currentStep() const { return m_current; }

    // Stepping: moves to step `index` (clamped); the step's scene (its working copy, if the
    // class changed it) replaces the scene, unless the step has an error (then the bar says
    // it and the scene stays). False when there was nowhere to go.
    bool goTo(int index);
    void next() { goTo(m_current + 1); }
    void previous() { goTo(m_current - 1); }
    void resetStep(); // the step as the lesson has it
    // The scene a step starts from: its working copy, else as authored.
    SceneFile stepScene(int index) const;

    // Authoring (lesson_authoring.cpp); each marks the lesson changed.
    void newLesson();     // one step: the current view
    void addViewAsStep(); // after the current step, and goes there
    void replaceStepWithView();
    // Refused (false, with a message) when empty or longer than a lesson's text may be.
    bool renameStep(const QString &title);
    bool setCaption(const LocalizedText &caption);
    void moveStep(int delta); // -1: up, +1: down
    bool removeStep();        // not the only step
    // Writes the lesson as authored; errors are shown and change nothing.
    bool save();
    bool saveAs(const QString &path);
    bool isModified() const { return m_open && m_modified; }

    // The lesson and step of the last session, opened again at the start with the session's
    // scene as that step's (the class's) working copy; a lesson gone since is forgotten.
    void restoreSession();

    // Whether `path` is a lesson file rather than a scene file (a dropped ".json"): a
    // regular file whose beginning names the lesson format.
    static bool isLessonFile(const QString &path);
    // The shipped lessons (":/lessons/*.json"): (title, resource).
    static QList<QPair<QString, QString>> shippedLessons();

    LessonBar *bar() const { return m_bar; }
    LessonMotion *motion() const { return m_motion; }
    RecentFiles *recent() const { return m_recent; }
    QMessageBox *messageBox() const { return m_messageBox; }
    QAction *nextAction() const { return m_nextAction; }
    QAction *previousAction() const { return m_previousAction; }

signals:
    void changed(); // opened, closed, stepped or edited: the title follows

private:
    // Where Open Lesson and Save Lesson As start (lesson_actions.cpp, lesson_authoring.cpp).
    static constexpr const char *kDirKey = "lessons/lastDirectory";

    void buildLessonMenu();
    void addLanguageMenu(); // Lesson > Caption Language, kept in the settings
    void showOpenDialog();
    void showSaveAsDialog();
    void showRenameDialog();
    void showCaptionDialog();
    void showMessage(QMessageBox::Icon icon, const QString &text, const QString &details);
    void keepWorkingCopy(); // the current step's scene, as the class left it
    void applyStep(const Scene &before);
    void pointAtStep();
    void showStep();
    void setOpen(bool open);
    void markModified();
    void updateActions();
    SceneFile currentView();
    void remember(); // the lesson file and step, for the next start

    MainWindow *m_window;
    LessonBar *m_bar;
    QSettings &m_settings;
    LessonMotion *m_motion;
    LessonKeys *m_keys;
    RecentFiles *m_recent;
    QMenu *m_menu;
    QPointer<QMessageBox> m_messageBox;
    std::function<bool(SetAsideFor, const QString &)> m_maySetAside;
    QAction *m_nextAction, *m_previousAction, *m_firstAction, *m_lastAction;
    QList<QAction *> m_needsLesson; // enabled while a lesson is open
    QAction *m_removeAction = nullptr;

    bool m_open = false;
    bool m_modified = false;
    Lesson m_lesson;
    QString m_path;
    int m_current = 0;
    std::vector<std::optional<SceneFile>> m_working; // per step: the class's edits
    bool m_shown = false; // the current step's scene is on screen (no error)
};

} // namespace lb
