#pragma once
// A child process that ends in bounded time and says so exactly once, through
// QProcess::finished: the grading batch's children, its frames' preparation and Check My
// Work's child all end this way.

#include <QProcess>

#include <functional>

namespace lb {

// A QProcess, child of `parent`, not started: connect to its finished(), then start() it.
// From start() on it is killed past `limitMs` (`timedOut` is told first, with the process), and
// a failure to start emits finished(-1, CrashExit), which QProcess does not do (its
// error() is then FailedToStart).
QProcess *boundedChild(QObject *parent, int limitMs, std::function<void(QProcess *)> timedOut = {});

} // namespace lb
