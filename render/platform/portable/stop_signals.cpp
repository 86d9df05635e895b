#include "stop_signals.h"

#include <QTimer>

#include <csignal>

namespace lb {

namespace {

// The signals standard C++ names, and SIGHUP where the system has one (POSIX: a closed
// terminal). Windows delivers Ctrl+C as SIGINT; Ctrl+Break (SIGBREAK) is left alone.
constexpr int kSignals[] = {SIGINT, SIGTERM,
#ifdef SIGHUP
                            SIGHUP
#endif
};
constexpr int kCount = int(sizeof kSignals / sizeof kSignals[0]);
volatile std::sig_atomic_t g_received = 0;

extern "C" void noteStop(int signal)
{
    if (g_received == 0)
        g_received = signal;
    // std::signal may have put the default handler back (the C standard allows it): again.
    std::signal(signal, noteStop);
}

} // namespace

struct StopSignals::Handlers
{
    void (*previous[kCount])(int) = {};
    QTimer poll;
};

StopSignals::StopSignals(QObject *parent) : QObject(parent), m_handlers(new Handlers)
{
    g_received = 0;
    for (int i = 0; i < kCount; ++i)
        m_handlers->previous[i] = std::signal(kSignals[i], noteStop);
    // No portable way for a handler to wake an event loop: it is looked at 20 times a second.
    m_handlers->poll.setInterval(50);
    connect(&m_handlers->poll, &QTimer::timeout, this, [this] {
        if (g_received != 0) {
            m_handlers->poll.stop();
            emit stopRequested(int(g_received));
        }
    });
    m_handlers->poll.start();
}

StopSignals::~StopSignals()
{
    for (int i = 0; i < kCount; ++i)
        if (m_handlers->previous[i] != SIG_ERR)
            std::signal(kSignals[i], m_handlers->previous[i]);
}

int StopSignals::received()
{
    return int(g_received);
}

} // namespace lb
