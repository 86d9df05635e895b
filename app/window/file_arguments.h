#pragma once
// FILE... on the command line, as the desktop's `lightbench %F` gives them: scene and lesson
// files opened in the window as File > Open Scene and File > Open Lesson open them, their
// messages included. The window shows one scene or lesson at a time: the first file opens,
// the others are named in one message.

#include <QString>
#include <QStringList>

namespace lb {

class MainWindow;

enum class DocumentKind { Scene, Lesson };

// A .lblesson file is a lesson and a .lbscene file a scene, whatever they hold (opening
// one that is not says why); any other (.json, the course's files) is a lesson when it says
// so at its start ("format": "lightbench-lesson"), else a scene.
DocumentKind documentKind(const QString &path);

// Opens `paths`' first file in `window`; true when it opened. One that cannot be opened (a
// missing file, a folder, a pipe, not a scene) leaves the window as it was, with the
// reader's message. The other files are named in one message box, object name below.
bool openFileArguments(MainWindow &window, const QStringList &paths);
inline constexpr const char *kFilesNotOpenedMessage = "filesNotOpenedMessage";

} // namespace lb
