#pragma once
// The command line's documents, written from the options it knows (command_line.h:
// visibleOptions()), so that neither can name an option the program lacks or miss one it
// has: the man page lightbench.1 (roff) and the bash completion. lightbench-docs
// (docs_main.cpp) writes both at build time; the tests read them from here.

#include <QString>

namespace lb {

// The man page, section 1: NAME, SYNOPSIS, DESCRIPTION, OPTIONS, FILES, ENVIRONMENT, EXIT
// STATUS, EXAMPLES, SEE ALSO.
QString manPage();
// `text` as roff prints it literally: backslashes, hyphens (as \-, the minus an option is
// typed with), a '.' or a '\'' that would start a request, and any character past ASCII
// (as \[uXXXX]) escaped.
QString roffEscaped(const QString &text);

// The bash completion (`complete -F _lightbench lightbench`): option names; for a value,
// the option's fixed words, files with the option's endings, or folders; for FILE..., scene
// and lesson files (any file after --grade).
QString bashCompletion();

} // namespace lb
