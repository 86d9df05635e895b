#include "bounded_child.h"

#include <QTimer>

namespace lb {

QProcess *boundedChild(QObject *parent, int limitMs, std::function<void(QProcess *)> timedOut)
{
    auto *p = new QProcess(parent);
    auto *timer = new QTimer(p);
    timer->setSingleShot(true);
    timer->setInterval(limitMs);
    // The clock runs from start() (the Starting state comes inside it), not from started(),
    // which a child stuck before its program runs would never send.
    QObject::connect(p, &QProcess::stateChanged, timer, [timer](QProcess::ProcessState state) {
        if (state == QProcess::Starting)
            timer->start();
    });
    QObject::connect(p, &QProcess::finished, timer, &QTimer::stop);
    QObject::connect(timer, &QTimer::timeout, p, [p, timedOut = std::move(timedOut)] {
        if (timedOut)
            timedOut(p);
        p->kill(); // finished() follows
    });
    QObject::connect(p, &QProcess::errorOccurred, p, [p](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart) // no finished() follows: say it ended
            emit p->finished(-1, QProcess::CrashExit);
    });
    return p;
}

} // namespace lb
