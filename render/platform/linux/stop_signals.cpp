#include "stop_signals.h"

#include <QSocketNotifier>

#include <cerrno>
#include <csignal>
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

struct StopSignals::Handlers
{
    struct sigaction previous[3];
    int pipe[2] = {-1, -1};
    QSocketNotifier *notifier = nullptr;
};

StopSignals::StopSignals(QObject *parent) : QObject(parent), m_handlers(new Handlers)
{
    g_received = 0;
    int *ends = m_handlers->pipe;
    if (::pipe(ends) == 0) {
        for (int i = 0; i < 2; ++i) {
            ::fcntl(ends[i], F_SETFD, FD_CLOEXEC); // not for the children
            ::fcntl(ends[i], F_SETFL, O_NONBLOCK); // a full pipe never blocks the handler
        }
    } else {
        ends[0] = ends[1] = -1; // received() still says it, at the batch's next step
    }
    g_writeEnd = ends[1];
    if (ends[0] >= 0) {
        m_handlers->notifier = new QSocketNotifier(ends[0], QSocketNotifier::Read, this);
        connect(m_handlers->notifier, &QSocketNotifier::activated, this, [this, ends] {
            char bytes[16];
            while (::read(ends[0], bytes, sizeof bytes) > 0) {
            }
            emit stopRequested(int(g_received));
        });
    }
    struct sigaction action = {};
    action.sa_handler = noteStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (int i = 0; i < 3; ++i)
        ::sigaction(kSignals[i], &action, &m_handlers->previous[i]);
}

StopSignals::~StopSignals()
{
    for (int i = 0; i < 3; ++i)
        ::sigaction(kSignals[i], &m_handlers->previous[i], nullptr);
    g_writeEnd = -1;
    delete m_handlers->notifier;
    for (int fd : m_handlers->pipe)
        if (fd >= 0)
            ::close(fd);
}

int StopSignals::received()
{
    return int(g_received);
}

} // namespace lb
