#include "unsaved_work.h"

#include <QAbstractButton>

namespace lb {

namespace {

// "the scene “lesson.json” and the shader files toon.vert and toon.frag"
QString names(const UnsavedWork &work)
{
    QString shaders;
    if (work.shaderFiles.size() == 1)
        shaders = QObject::tr("the shader file %1").arg(work.shaderFiles[0]);
    else if (work.shaderFiles.size() > 1)
        shaders =
            QObject::tr("the shader files %1 and %2")
                .arg(QStringList(work.shaderFiles.mid(0, work.shaderFiles.size() - 1)).join(", "),
                     work.shaderFiles.last());
    if (work.lesson) {
        const QString lesson = QObject::tr("the lesson \u201c%1\u201d").arg(work.lessonName);
        return shaders.isEmpty() ? lesson : QObject::tr("%1 and %2").arg(lesson, shaders);
    }
    if (!work.scene)
        return shaders;
    const QString scene = work.sceneName.isEmpty()
                              ? QObject::tr("the untitled scene")
                              : QObject::tr("the scene \u201c%1\u201d").arg(work.sceneName);
    return shaders.isEmpty() ? scene : QObject::tr("%1 and %2").arg(scene, shaders);
}

} // namespace

QString unsavedWorkQuestion(const UnsavedWork &work, SetAsideFor occasion, const QString &target)
{
    switch (occasion) {
    case SetAsideFor::Closing:
        return QObject::tr("Save the changes to %1 before closing?").arg(names(work));
    case SetAsideFor::OpeningScene:
    case SetAsideFor::OpeningLesson:
        return QObject::tr("Save the changes to %1 before opening \u201c%2\u201d?")
            .arg(names(work), target);
    case SetAsideFor::ResettingEverything:
        return QObject::tr("Save the changes to %1 before resetting everything?").arg(names(work));
    case SetAsideFor::ClosingLesson:
        return QObject::tr("Save the changes to %1 before closing it?").arg(names(work));
    }
    return {};
}

QString unsavedWorkDetails(const UnsavedWork &work)
{
    return work.shaderFiles.size() + (work.scene || work.lesson ? 1 : 0) > 1
               ? QObject::tr("Your changes will be lost if you don't save them. Save saves them "
                             "all.")
               : QObject::tr("Your changes will be lost if you don't save them.");
}

QMessageBox::StandardButton askAboutUnsavedWork(QWidget *parent, const QString &question,
                                                const QString &details)
{
    QMessageBox box(QMessageBox::Warning, QObject::tr("Unsaved changes"), question,
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, parent);
    box.setObjectName("unsavedWorkQuestion");
    box.setInformativeText(details);
    // Some desktops word Discard "Close without Saving", wrong before opening or resetting.
    box.button(QMessageBox::Discard)->setText(QObject::tr("Discard"));
    box.setDefaultButton(QMessageBox::Save);
    box.setEscapeButton(QMessageBox::Cancel);
    box.exec();
    const QMessageBox::StandardButton answer = box.standardButton(box.clickedButton());
    return answer == QMessageBox::Save || answer == QMessageBox::Discard ? answer
                                                                         : QMessageBox::Cancel;
}

} // namespace lb
