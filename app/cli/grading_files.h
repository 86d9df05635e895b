#pragma once
// What --grade and its child (--grade-one) both use: the exercise file, checked; where a
// submission's sheet goes; a line printed and flushed at once.

#include "diagnostics.h"
#include "scene_file.h"

#include <QString>
#include <QStringList>

#include <cstdio>

namespace lb {

// The exercise file, checked: "PATH: why" when it cannot be graded against. A field of the
// exercise section that cannot be used is an error too: a misspelt "vary" would grade every
// case alike and pass wrong answers without a word.
struct ExerciseFile
{
    SceneFile file;
    QString error;
    QStringList ignored; // the scene's own fields that could not be used
};
ExerciseFile readExerciseFile(const QString &path);

// "WHO fragment:12: message", "WHO (link): message": a diagnostic of a program the exercise
// holds inline (its reference, WHO "reference"; a known mistake, "mistake 2 (normal matrix)").
QString exerciseProgramText(const QString &who, const Diagnostic &d);

// FOLDER/NAME.png.
QString gradingSheetPath(const QString &folder, const QString &name);

// `line` and a line break on `stream`, flushed: a batch's reader sees each line as it comes.
void printLine(const QString &line, FILE *stream);

} // namespace lb
