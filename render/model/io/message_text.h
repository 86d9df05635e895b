#pragma once
// Values echoed in messages, kept to a readable length: a 60 MB path or 200,000 ignored
// fields made lines of tens of megabytes (a terminal, a log, a message box that never opens).

#include <QString>
#include <QStringList>

namespace lb {

// `text` itself up to `max` characters; longer, its start and end around "...".
QString elidedForMessage(const QString &text, int max = 200);
// A value the user typed or a file named (a path, an argument), as one line of a message:
// elided as above, and line breaks and other control characters shown as U+FFFD.
QString echoedValue(const QString &text, int max = 200);
// A file's path as a message names it: echoedValue with room for a deep folder (300).
QString echoedPath(const QString &path);
// A name shown as it is spelt, on one line that a terminal, a CSV cell or a label cannot
// misread (issue 29: a submission named "x\nalice: passed, 20/20 ..." printed a fake result
// line; ESC sequences recoloured the terminal): line breaks, tabs, ESC, every other C0 and C1
// control and DEL as escapes (`\n`, `\r`, `\t`, `\x1b`, `\x85`, `\x7f`), the Unicode line and
// paragraph separators and the direction controls that reorder what follows as `\u2028`,
// `\u202e`, and a backslash as `\\`, so that an escape shown cannot be typed into a name. For
// submission names, scene, file and exercise titles: wherever a name goes, not the text around.
QString escapedName(const QString &name);
// The same for the text around names (a diagnostic that names a file whose name was escaped
// where it was written, a driver's message): controls escaped, backslashes left as they are,
// so that an escaped name is not escaped twice.
QString escapedControls(const QString &text);
// The first `shown` items (each elided), joined by `separator`, then "... and N more".
QString summarisedList(const QStringList &items, const QString &separator, int shown = 8);

// A sentence with a count, through Qt's plural forms: `source` holds %n and is marked for
// lupdate where it is written, with QT_TRANSLATE_N_NOOP(context, ...). Where no translation of
// it is loaded (the command line installs no translator; the window in English) Qt gives the
// source as it is, "1 object(s)"; English's own form is given instead, "(s)" dropped for 1
// and "s" for any other count, so that English reads as it did before it was marked.
QString countedText(const char *context, const char *source, int n);

} // namespace lb
