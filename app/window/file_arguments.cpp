#include "file_arguments.h"

#include "lesson_actions.h"
#include "main_window.h"
#include "message_text.h"
#include "scene_actions.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>

namespace lb {

namespace {

// The translation context of these messages ("lb::FileArguments" in the .ts files).
struct FileArguments
{
    Q_DECLARE_TR_FUNCTIONS(lb::FileArguments)
};

} // namespace

DocumentKind documentKind(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == "lblesson")
        return DocumentKind::Lesson;
    if (suffix == "lbscene")
        return DocumentKind::Scene;
    return LessonActions::isLessonFile(path) ? DocumentKind::Lesson : DocumentKind::Scene;
}

bool openFileArguments(MainWindow &window, const QStringList &paths)
{
    if (paths.isEmpty())
        return false;
    const QString &first = paths.first();
    bool opened = false;
    if (documentKind(first) == DocumentKind::Lesson) {
        opened = window.lessonActions()->openAsking(first, 0);
    } else {
        opened = window.sceneActions()->openAsking(first);
        if (opened) // the last session's lesson gives way to the scene asked for
            window.lessonActions()->closeLesson();
    }
    if (paths.size() > 1) {
        QStringList others;
        for (qsizetype i = 1; i < paths.size(); ++i)
            others << escapedName(QFileInfo(paths[i]).fileName());
        auto *box = new QMessageBox(
            QMessageBox::Information, FileArguments::tr("Files not opened"),
            FileArguments::tr(
                "lightbench opens one scene or lesson at a time, the first file given "
                "(%1); the files below were not opened. Open them with File > "
                "Open Scene or File > Open Lesson.")
                .arg(escapedName(QFileInfo(first).fileName())),
            QMessageBox::Ok, &window);
        box->setInformativeText(summarisedList(others, "\n", 20));
        box->setObjectName(kFilesNotOpenedMessage);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setWindowModality(Qt::NonModal);
        box->show();
    }
    return opened;
}

} // namespace lb
