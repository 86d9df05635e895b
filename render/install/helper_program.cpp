#include "helper_program.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace lb {

namespace {

bool isRunnable(const QString &path)
{
    const QFileInfo info(path);
    return info.isFile() && info.isExecutable();
}

} // namespace

QString installedHelperDir()
{
    return QStringLiteral(LB_HELPERS_FROM_BINDIR);
}

QString helperProgramPath(const QString &givenName, const char *environmentVariable,
                          const QString &executableDir)
{
#ifdef Q_OS_WIN
    const QString name = givenName + QStringLiteral(".exe");
#else
    const QString &name = givenName;
#endif
    const QString fromEnvironment = qEnvironmentVariable(environmentVariable);
    if (!fromEnvironment.isEmpty())
        return fromEnvironment;
    const QDir dir(executableDir);
    const QString beside = dir.filePath(name);
    if (isRunnable(beside))
        return beside;
    const QString installed = QDir::cleanPath(dir.filePath(installedHelperDir() + '/' + name));
    if (isRunnable(installed))
        return installed;
    const QString onPath = QStandardPaths::findExecutable(name);
    return onPath.isEmpty() ? installed : onPath;
}

QString helperProgramPath(const QString &name, const char *environmentVariable)
{
    return helperProgramPath(name, environmentVariable, QCoreApplication::applicationDirPath());
}

} // namespace lb
