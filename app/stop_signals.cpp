#include "stop_signals.h"

#include <QSocketNotifier>

#include <cerrno>
#include <fcntl.h>
#include <unistd.h>

namespace lb {

namespace {

constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_received = 0;
int g_writeEnd = -1;

void noteStop(int signal)
{
    const int saved = errno;
    if (g_received == 0)
        g_received = signal;
    if (g_writeEnd >= 0) {
        const char byte = char(signal);
        [[maybe_unused]] const ssize_t n = ::write(g_writeEnd, &byte, 1);
    }
    errno = saved;
}

} // namespace

StopSignals::StopSignals(QObject *parent) : QObject(parent)
{
    g_received = 0;
    if (::pipe(m_pipe) == 0) {
        for (int fd : m_pipe) {
            ::fcntl(fd, F_SETFD, FD_CLOEXEC); // not for the children
            ::fcntl(fd, F_SETFL, O_NONBLOCK); // a full pipe never blocks the handler
        }
    } else {
        m_pipe[0] = m_pipe[1] = -1; // received() still says it, at the batch's next step
    }
    g_writeEnd = m_pipe[1];
    if (m_pipe[0] >= 0) {
        m_notifier = new QSocketNotifier(m_pipe[0], QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, [this] {
            char bytes[16];
            while (::read(m_pipe[0], bytes, sizeof bytes) > 0) {
            }
            emit stopRequested(int(g_received));
        });
    }
    struct sigaction action = {};
    action.sa_handler = noteStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (int i = 0; i < 3; ++i)
        ::sigaction(kSignals[i], &action, &m_previous[i]);
}

StopSignals::~StopSignals()
{
    for (int i = 0; i < 3; ++i)
        ::sigaction(kSignals[i], &m_previous[i], nullptr);
    g_writeEnd = -1;
    delete m_notifier;
    for (int fd : m_pipe)
        if (fd >= 0)
            ::close(fd);
}

int StopSignals::received()
{
    return int(g_received);
}

} // namespace lb
