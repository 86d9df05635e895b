#pragma once
// A program run to its end for a test: its exit code (-1: still running after the limit, then
// killed; -2: it crashed), its standard output and its standard error.

#include <QByteArray>
#include <QProcess>
#include <QString>
#include <QStringList>

struct ProgramRun
{
    int exitCode;
    QByteArray out, err;
};

inline ProgramRun runProgram(const QString &program, const QStringList &args, int limitMs)
{
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(limitMs))
        return {-1, {}, "timed out"};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError()};
}
