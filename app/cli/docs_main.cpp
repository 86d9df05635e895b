// lightbench-docs DIR: writes DIR/lightbench.1 (the man page) and DIR/lightbench (the bash
// completion, named as bash-completion looks it up) from the options lightbench knows
// (cli_docs.h). Run by the build (the lightbench_docs target), not installed.

#include "cli_docs.h"
#include "safe_write.h"

#include <QDir>

#include <cstdio>

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fputs("usage: lightbench-docs DIR (writes DIR/lightbench.1 and DIR/lightbench)\n",
                   stderr);
        return 2;
    }
    const QDir dir(QString::fromLocal8Bit(argv[1]));
    if (!dir.mkpath(".")) {
        std::fprintf(stderr, "lightbench-docs: %s: cannot make the folder\n", argv[1]);
        return 1;
    }
    // Both or neither: a build that stopped half-way leaves no page beside an old completion.
    const QString error =
        lb::writeFilesSafely({{dir.filePath("lightbench.1"), lb::manPage().toUtf8()},
                              {dir.filePath("lightbench"), lb::bashCompletion().toUtf8()}});
    if (!error.isEmpty()) {
        std::fprintf(stderr, "lightbench-docs: %s\n", qPrintable(error));
        return 1;
    }
    return 0;
}
