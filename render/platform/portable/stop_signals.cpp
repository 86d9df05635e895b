#include "stop_signals.h"

#include <QTimer>

#include <csignal>

namespace lb {

namespace {

// The signals standard C++ names (SIGHUP is POSIX's; Windows delivers Ctrl+C as SIGINT and
// Ctrl+Break as SIGBREAK, which this layer leaves alone).
constexpr int kSignals[2] = {SIGINT, SIGTERM};
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
    void (*previous[2])(int) = {SIG_DFL, SIG_DFL};
    QTimer poll;
};

StopSignals::StopSignals(QObject *parent) : QObject(parent), m_handlers(new Handlers)
{
    g_received = 0;
    for (int i = 0; i < 2; ++i)
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
    for (int i = 0; i < 2; ++i)
        if (m_handlers->previous[i] != SIG_ERR)
            std::signal(kSignals[i], m_handlers->previous[i]);
}

int StopSignals::received()
{
    return int(g_received);
}

} // namespace lb
