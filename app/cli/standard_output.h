#pragma once
// What the command line's runs print on standard output as their result (--probe's and
// --bench-frames' JSON, a report to "-"): written whole and flushed, or the run fails with the
// reason. A stdout closed when lightbench started is open on the null device by then (main,
// platform::reopenClosedStandardStreams), so writing to it would succeed and lose the result.

#include <QByteArray>
#include <QString>

namespace lb {

// main tells it once: whether descriptor 1 was closed when lightbench started.
void setStandardOutputWasClosed(bool closed);

// `bytes` on standard output, flushed; empty when they all got there, else the reason:
// "standard output is closed" or "could not write to standard output (No space left on
// device)".
QString writeStandardOutput(const QByteArray &bytes);

} // namespace lb
