#include "unsaved_work.h"

#include <QAbstractButton>

namespace lb {

namespace {

// "the scene “lesson.json” and the shader files toon.vert and toon.frag": what the question
// asks about, as the object of "Save the changes to %1 ...". Each piece is a whole noun phrase
// for translators (in that one place, so its grammatical case is known).
QString names(const UnsavedWork &work)
{
    QString shaders;
    if (work.shaderFiles.size() == 1)
        //: goes into "Save the changes to %1 before ...?"
        shaders = UnsavedWork::tr("the shader file %1").arg(work.shaderFiles[0]);
    else if (work.shaderFiles.size() > 1)
        //: goes into "Save the changes to %1 before ...?"; %1 and %2 are NAME.vert, NAME.frag
        shaders =
            UnsavedWork::tr("the shader files %1 and %2")
                .arg(QStringList(work.shaderFiles.mid(0, work.shaderFiles.size() - 1)).join(", "),
                     work.shaderFiles.last());
    QString document;
    if (work.lesson)
        //: goes into "Save the changes to %1 before ...?"
        document = UnsavedWork::tr("the lesson \u201c%1\u201d").arg(work.lessonName);
    else if (work.scene)
        document = work.sceneName.isEmpty()
                       //: goes into "Save the changes to %1 before ...?"
                       ? UnsavedWork::tr("the untitled scene")
                       //: goes into "Save the changes to %1 before ...?"
                       : UnsavedWork::tr("the scene \u201c%1\u201d").arg(work.sceneName);
    if (document.isEmpty() || shaders.isEmpty())
        return document.isEmpty() ? shaders : document;
    //: the lesson or the scene (%1) and the shader files (%2), in "Save the changes to %1"
    return UnsavedWork::tr("%1 and %2").arg(document, shaders);
}

} // namespace

QString unsavedWorkQuestion(const UnsavedWork &work, SetAsideFor occasion, const QString &target)
{
    switch (occasion) {
    case SetAsideFor::Closing:
        return UnsavedWork::tr("Save the changes to %1 before closing?").arg(names(work));
    case SetAsideFor::OpeningScene:
    case SetAsideFor::OpeningLesson:
        return UnsavedWork::tr("Save the changes to %1 before opening \u201c%2\u201d?")
            .arg(names(work), target);
    case SetAsideFor::ResettingEverything:
        return UnsavedWork::tr("Save the changes to %1 before resetting everything?")
            .arg(names(work));
    case SetAsideFor::ClosingLesson:
        return UnsavedWork::tr("Save the changes to %1 before closing it?").arg(names(work));
    case SetAsideFor::NewLesson:
        return UnsavedWork::tr("Save the changes to %1 before starting a new lesson?")
            .arg(names(work));
    }
    return {};
}

QString unsavedWorkDetails(const UnsavedWork &work)
{
    return work.shaderFiles.size() + (work.scene || work.lesson ? 1 : 0) > 1
               ? UnsavedWork::tr("Your changes will be lost if you don't save them. Save saves "
                                 "them all.")
               : UnsavedWork::tr("Your changes will be lost if you don't save them.");
}

UnsavedWorkAnswer askAboutUnsavedWork(QWidget *parent, const QString &question,
                                      const QString &details)
{
    QMessageBox box(QMessageBox::Warning, UnsavedWork::tr("Unsaved changes"), question,
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, parent);
    box.setObjectName("unsavedWorkQuestion");
    box.setInformativeText(details);
    // Some desktops word Discard "Close without Saving", wrong before opening or resetting.
    box.button(QMessageBox::Discard)->setText(UnsavedWork::tr("Discard"));
    box.setDefaultButton(QMessageBox::Save);
    box.setEscapeButton(QMessageBox::Cancel);
    box.exec();
    const QMessageBox::StandardButton answer = box.standardButton(box.clickedButton());
    return answer == QMessageBox::Save || answer == QMessageBox::Discard ? answer
                                                                         : QMessageBox::Cancel;
}

} // namespace lb
