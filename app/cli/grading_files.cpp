#include "grading_files.h"

#include "message_text.h"

#include <QDir>

namespace lb {

ExerciseFile readExerciseFile(const QString &path)
{
    ExerciseFile e;
    const SceneFileRead read = readSceneFile(path);
    QStringList exerciseFields;
    for (const QString &i : read.ignored)
        (i.startsWith("exercise") ? exerciseFields : e.ignored) << i;
    if (!read.file)
        e.error = read.error;
    else if (!read.exerciseError.isEmpty())
        e.error = QString("%1: %2").arg(path, read.exerciseError);
    else if (!read.file->exercise)
        e.error =
            QString("%1: not an exercise (the scene file has no \"exercise\" section)").arg(path);
    else if (!exerciseFields.isEmpty())
        e.error = QString("%1: %2").arg(path, summarisedList(exerciseFields, "; "));
    else
        e.file = *read.file;
    return e;
}

QString exerciseProgramText(const QString &who, const Diagnostic &d)
{
    const QString where = d.stage == ShaderStage::Link
                              ? QString("%1 (link)").arg(who)
                              : QString("%1 %2").arg(who, stageName(d.stage));
    return d.line > 0 ? QString("%1:%2: %3").arg(where, QString::number(d.line), d.message)
                      : QString("%1: %2").arg(where, d.message);
}

QString gradingSheetPath(const QString &folder, const QString &name)
{
    return QDir(folder).filePath(name + ".png");
}

void printLine(const QString &line, FILE *stream)
{
    std::fputs(qPrintable(line + "\n"), stream);
    std::fflush(stream);
}

} // namespace lb
