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
// The first `shown` items (each elided), joined by `separator`, then "... and N more".
QString summarisedList(const QStringList &items, const QString &separator, int shown = 8);

} // namespace lb
