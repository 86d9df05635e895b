#pragma once
// A batch that is stopped (Ctrl+C: SIGINT, `kill`: SIGTERM, a closed terminal: SIGHUP where
// the system has it) hears of it in its event loop, so it can stop its children and keep
// what it finished, then exit with 128 + the signal as a shell expects. The handler only
// notes the signal (all a signal handler may safely do) and wakes the event loop: Linux
// through a pipe and a socket notifier, the portable layer by a timer that looks at the note.
// The previous handlers come back when this goes.

#include <QObject>

#include <memory>

namespace lb {

class StopSignals : public QObject
{
    Q_OBJECT
public:
    explicit StopSignals(QObject *parent = nullptr);
    ~StopSignals() override;

    // The first stop signal that came, 0 while none did: true from the moment the handler
    // ran, also before the event loop has said so.
    static int received();
    static int exitCodeFor(int signal) { return 128 + signal; }

signals:
    void stopRequested(int signal);

private:
    struct Handlers; // the system's side: previous handlers, the wake-up
    std::unique_ptr<Handlers> m_handlers;
};

} // namespace lb
