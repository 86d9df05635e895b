#pragma once
// A student's submission as --grade names it: NAME.vert + NAME.frag (either file, or NAME
// alone), a folder holding one such pair, or a scene file with a program.

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace lb {

struct Submission
{
    // Its messages: English on the command line (no translator), translated in the window.
    Q_DECLARE_TR_FUNCTIONS(lb::Submission)
public:
    QString name;                     // NAME, the folder's or the scene file's base name
    QString vertexPath, fragmentPath; // for messages: where each stage's lines are
    QString vertex, fragment;
    QString error; // "PATH: why" when it cannot be read; empty otherwise
};

Submission readSubmission(const QString &path);

// The submissions among `paths`, each once, in the order given: NAME.vert and NAME.frag (and
// NAME) name one submission, so `--grade submissions/*` over a folder of pairs grades each
// student once.
QStringList distinctSubmissions(const QStringList &paths);

} // namespace lb
