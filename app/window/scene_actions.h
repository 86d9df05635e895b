#pragma once
// The window's scene files and images: File > Open Scene, Save Scene (As), Open Recent
// Scene, Examples (the scenes in resources/examples), Export Image at a chosen size and Copy
// Image. A scene file carries the editor's program, so these act on the document and the
// editor together.

#include "scene_file.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

class QMainWindow;
class QMenu;
class QSettings;

namespace lb {

class RecentFiles;
class SceneDocument;
class ShaderDocument;
class Viewport;

class SceneActions : public QObject
{
    Q_OBJECT
public:
    SceneActions(QMainWindow *window, SceneDocument *document, ShaderDocument *shaders,
                 Viewport *viewport, QSettings &settings);

    void addToMenu(QMenu *file);

    // Opens a scene file: the scene, its program and its mesh replace the current ones; a
    // file that cannot be used changes nothing. Returns false then (the message is shown).
    bool open(const QString &path);
    // What open() does once the file is read, for a scene that is not a file of its own (a
    // lesson's step): `file` replaces the scene, its program and its exercise; `ignored`
    // (what its reading could not use) is shown once. `origin`: the file (absolute) or
    // ":/..." resource it came from, kept for Save and the next start; empty for none.
    void apply(const SceneFile &file, const QStringList &ignored, const QString &origin);
    // The user's open (File > Open Scene, Open Recent Scene, Examples, a dropped file): asks
    // setMaySetAside()'s question first (`shownName` names the scene in it, the file's name
    // if empty); false when the answer is Cancel or the file did not open.
    bool openAsking(const QString &path, const QString &shownName = {});
    // Whether the work not yet saved may be set aside for the scene named `target`
    // (MainWindow::maySetAside). None: it may.
    void setMaySetAside(std::function<bool(const QString &target)> ask)
    {
        m_maySetAside = std::move(ask);
    }
    // Writes the current scene and program; returns an empty string or the message shown.
    QString save(const QString &path);
    // File > Save Scene: to the scene's file, or Save As for a scene without one. True once
    // written; false when the dialog was cancelled or the save failed (the message is shown).
    bool saveScene();
    // The scene a save writes and isModified() compares: the document's, unless the window
    // shows something that is not the user's own (an exercise's case, main_window_exercise).
    void setSceneToSave(std::function<Scene()> scene) { m_sceneToSave = std::move(scene); }
    QString currentPath() const { return m_path; }
    // The scene's name for the title: the file's, an example's, or empty (none opened).
    QString documentName() const { return m_name; }
    // Whether the scene or its program changed since it was opened or saved; with none
    // opened, whether anything differs from the defaults.
    bool isModified() const;
    // The same for the scene alone, its program aside (a shader pair's files hold it).
    bool isSceneModified() const;
    // What isModified() compares with: the file as last opened or saved; the defaults (and
    // the built-in program) when none was.
    SceneFile savedFile() const;
    // No file from now on (Reset Everything): the title says untitled, Save asks for a name.
    void forgetFile();
    // Renders the view at `pixels` and writes it (PNG unless the name says otherwise).
    QString exportImage(const QString &path, QSize pixels);
    void copyImage();

    RecentFiles *recent() const { return m_recent; }
    // The message of the last scene that opened with fields ignored or failed, while open.
    QMessageBox *messageBox() const { return m_messageBox; }
    // The example scenes: (menu text, resource path).
    static QList<QPair<QString, QString>> examples();

    bool showSaveDialog(); // false: cancelled, or the save failed

    // The open scene file's exercise (exercise.h), if it has one.
    const std::optional<Exercise> &exercise() const { return m_exercise; }
    // The exercise's scene as its file has it: the base of its cases, whatever the student
    // changed since.
    const Scene &exerciseScene() const { return m_exerciseScene; }
    // The exercise of `file` (and its scene, the base of its cases) without its scene or
    // program: the session's scene and program are the student's, kept from the last
    // session, and a lesson's step saves no exercise of its own (LessonActions::restoreSession).
    void restoreExercise(const SceneFile &file);

signals:
    void sceneOpened(const QString &origin); // apply()'s origin: empty for a lesson's step
    // The open scene's exercise came or went (exercise()): side B shows its reference.
    void exerciseChanged();
    void documentChanged(); // opened, saved, or another name

private:
    void showOpenDialog();
    void showExportDialog();
    void showMessage(QMessageBox::Icon icon, const QString &text, const QString &details);
    // The scene's file (absolute), an example's resource, or none; kept for the next start.
    void setDocument(const QString &origin);
    void remember(); // what isModified() compares with
    Scene sceneToSave() const;
    bool differsFromSaved(bool withProgram) const;

    QMainWindow *m_window;
    SceneDocument *m_document;
    ShaderDocument *m_shaders;
    Viewport *m_viewport;
    QSettings &m_settings;
    RecentFiles *m_recent;
    QPointer<QMessageBox> m_messageBox;
    std::function<Scene()> m_sceneToSave;
    std::function<bool(const QString &)> m_maySetAside;
    QString m_path; // the scene file last opened or saved; empty for an example or none
    QString m_name;
    std::optional<SceneFile> m_saved;
    std::optional<Exercise> m_exercise; // the open scene file's, kept when it is saved
    Scene m_exerciseScene;
};

} // namespace lb
