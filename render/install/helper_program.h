#pragma once
// Where lightbench's helper programs (lightbench-import, lightbench-trial) are, for the
// workbench that starts them (ImportProcess, TrialProcess): one lookup for both.

#include <QString>

namespace lb {

// The helper `name`, the first of:
//   1. $environmentVariable, when set (the tests, a developer trying another build of it);
//   2. beside the running executable (the build tree keeps all three in build/app/);
//   3. the installed layout, <bindir>/../<libexecdir>/lightbench/ taken relative to the
//      executable's folder, so a tree installed or unpacked into any prefix finds its own;
//   4. on the PATH.
// Found nowhere: the installed layout's path, so that "cannot start" names where it should be.
QString helperProgramPath(const QString &name, const char *environmentVariable);
// The same, from `executableDir` instead of the running executable's folder.
QString helperProgramPath(const QString &name, const char *environmentVariable,
                          const QString &executableDir);

// The installed helpers' folder relative to the installed executable's ("../libexec/lightbench"
// with GNUInstallDirs' defaults), as configured.
QString installedHelperDir();

} // namespace lb
