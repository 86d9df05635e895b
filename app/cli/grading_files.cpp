#include "grading_files.h"

#include "message_text.h"
#include "safe_write.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>

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
    // A file name has at most 255 bytes: a student folder of 253 ended the whole batch (its
    // sheet's name would not do). A longer one is cut between characters and told apart from
    // others cut the same way by the start of its whole name's hash.
    constexpr int kMaxNameBytes = 255;
    const QString whole = name + ".png";
    if (QFile::encodeName(whole).size() <= kMaxNameBytes)
        return QDir(folder).filePath(whole);
    const QString hash = QString::fromLatin1(
        QCryptographicHash::hash(name.toUtf8(), QCryptographicHash::Sha1).toHex().left(8));
    return QDir(folder).filePath(leftInBytes(name, kMaxNameBytes - 13) + "-" + hash + ".png");
}

void printLine(const QString &line, FILE *stream)
{
    std::fputs(qPrintable(line + "\n"), stream);
    std::fflush(stream);
}

} // namespace lb
