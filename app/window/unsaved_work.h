#pragma once
// Work not yet in its files, and the question asked before something sets it aside: quit or
// close, another scene opened over it, Reset Everything. Save / Discard / Cancel, the desktop
// convention. The window decides when to ask (MainWindow::maySetAside); this names what is
// unsaved and asks.

#include <QCoreApplication>
#include <QMessageBox>
#include <QString>
#include <QStringList>

#include <functional>

namespace lb {

// What the title's * stands for, named for the question.
struct UnsavedWork
{
    Q_DECLARE_TR_FUNCTIONS(lb::UnsavedWork) // the question's words (context lb::UnsavedWork)
public:
    bool scene = false;      // the scene (settings and program) has unsaved changes
    QString sceneName;       // its file's (or example's) name; empty: untitled
    QStringList shaderFiles; // the shader files (NAME.vert, NAME.frag) with unsaved edits
    // While a lesson is open it is the document (lesson_actions.h): its authoring changes.
    bool lesson = false;
    QString lessonName{};
    bool any() const { return scene || !shaderFiles.isEmpty() || lesson; }
};

// What would set the work aside.
enum class SetAsideFor {
    Closing,
    OpeningScene,
    ResettingEverything,
    OpeningLesson,
    ClosingLesson,
    NewLesson
};

// The answer: Save, Discard or Cancel (anything else reads as Cancel). A name of its own also
// keeps lupdate from reading the definition below as QMessageBox's, in the wrong context.
using UnsavedWorkAnswer = QMessageBox::StandardButton;
// Who answers the question: the user in askAboutUnsavedWork()'s message box, or a test.
using UnsavedWorkAsker = std::function<UnsavedWorkAnswer(QWidget *parent, const QString &question,
                                                         const QString &details)>;

// The question's text, one whole sentence per occasion (for translators): "Save the changes
// to the scene “lesson.json” before closing?". `target` is the scene or lesson about to be
// opened (not used for the other occasions).
QString unsavedWorkQuestion(const UnsavedWork &work, SetAsideFor occasion,
                            const QString &target = {});
QString unsavedWorkDetails(const UnsavedWork &work);

// A modal message box (object name "unsavedWorkQuestion"): Save (the default: Return never
// throws work away), Discard, Cancel (Esc and the title bar's close).
UnsavedWorkAnswer askAboutUnsavedWork(QWidget *parent, const QString &question,
                                      const QString &details);

} // namespace lb
