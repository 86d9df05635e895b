#pragma once
// A batch that is stopped (Ctrl+C: SIGINT, `kill`: SIGTERM, a closed terminal: SIGHUP) hears
// of it in its event loop, so it can stop its children and keep what it finished, then exit
// with 128 + the signal as a shell expects. The handler only notes the signal and writes a
// byte to a pipe (all a signal handler may safely do); a notifier on the pipe's other end
// says it in the event loop. The previous handlers come back when this goes.

#include <QObject>

#include <csignal>
#include <memory>

class QSocketNotifier;

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
    struct sigaction m_previous[3];
    int m_pipe[2] = {-1, -1};
    QSocketNotifier *m_notifier = nullptr;
};

} // namespace lb
