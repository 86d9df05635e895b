#include "trial_process.h"

#include "helper_program.h"
#include "work_guard.h"

#include <QEventLoop>

namespace lb {

namespace {

constexpr qsizetype kStderrKept = 2048;
// Helpers that died before answering anything, in a row: then there is no use starting more.
constexpr int kMaxSilentDeaths = 3;

} // namespace

TrialProcess::TrialProcess(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<lb::TrialResult>();
    qRegisterMetaType<lb::TrialProcess::Outcome>();
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &TrialProcess::timedOut);
}

TrialProcess::~TrialProcess()
{
    for (QProcess *process : findChildren<QProcess *>()) {
        process->disconnect(this);
        process->kill();
        process->waitForFinished(2000);
    }
}

QString TrialProcess::helperPath()
{
    return helperProgramPath(QStringLiteral("lightbench-trial"), "LIGHTBENCH_TRIAL_HELPER");
}

qint64 TrialProcess::helperPid() const
{
    return m_process ? m_process->processId() : 0;
}

void TrialProcess::startHelper()
{
    auto *process = new QProcess(this);
    connect(process, &QProcess::readyReadStandardOutput, this, [this, process] {
        if (process == m_process)
            readOutput();
    });
    connect(process, &QProcess::readyReadStandardError, this, [this, process] {
        m_stderr += process->readAllStandardError();
        if (m_stderr.size() > kStderrKept)
            m_stderr = m_stderr.right(kStderrKept);
    });
    connect(process, &QProcess::finished, this, [this, process] { helperEnded(process); });
    connect(process, &QProcess::errorOccurred, this, [this, process](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart)
            helperEnded(process);
    });
    m_process = process;
    m_output.clear();
    m_meshSent = false;
    m_sentMesh.reset();
    process->start(helperPath(), {}, QIODevice::ReadWrite);
}

void TrialProcess::tryProgram(const trialwire::TryRequest &request,
                              std::shared_ptr<const Mesh> mesh)
{
    Pending pending{request, std::move(mesh)};
    if (!m_available) {
        answer(request.id, Outcome::Unavailable);
        return;
    }
    if (m_inFlight) {
        m_waiting = std::move(pending);
        return;
    }
    send(pending);
}

TrialProcess::Answer TrialProcess::tryAndWait(const trialwire::TryRequest &request,
                                              std::shared_ptr<const Mesh> mesh)
{
    Answer answer;
    QEventLoop loop;
    const QMetaObject::Connection connection =
        connect(this, &TrialProcess::finished, &loop,
                [&](quint64 id, Outcome outcome, const TrialResult &result,
                    const std::vector<Diagnostic> &diagnostics) {
                    if (id != request.id)
                        return;
                    answer = Answer{outcome, result, diagnostics};
                    loop.quit();
                });
    tryProgram(request, std::move(mesh));
    loop.exec(QEventLoop::ExcludeUserInputEvents);
    disconnect(connection);
    return answer;
}

void TrialProcess::send(const Pending &pending)
{
    // In flight before anything is written: a helper that fails to start may say so while
    // the bytes are being written (helperEnded), and answers for it.
    m_inFlight = pending;
    m_deadline.start(m_limitMs);
    if (!m_process)
        startHelper();
    if (!m_process)
        return; // it could not start, and helperEnded() has answered
    if (!m_meshSent || m_sentMesh.lock() != pending.mesh) {
        m_process->write(
            trialwire::framed(trialwire::encodeMesh(pending.mesh ? *pending.mesh : Mesh{})));
        m_sentMesh = pending.mesh;
        m_meshSent = true;
    }
    m_process->write(trialwire::framed(trialwire::encodeTry(pending.request)));
    // Written now, not when the event loop next runs: the window may be busy a while (the
    // driver generating the program's code) and the helper can start meanwhile.
    m_process->waitForBytesWritten(0);
}

void TrialProcess::sendNext()
{
    if (m_inFlight || !m_waiting)
        return;
    Pending next = std::move(*m_waiting);
    m_waiting.reset();
    if (m_available)
        send(next);
    else
        answer(next.request.id, Outcome::Unavailable);
}

void TrialProcess::readOutput()
{
    m_output += m_process->readAllStandardOutput();
    while (const std::optional<QByteArray> frame = trialwire::takeFrame(m_output)) {
        const std::optional<trialwire::Decoded> message = trialwire::decode(*frame);
        if (!message || !m_inFlight || message->reply.id != m_inFlight->request.id)
            continue;
        if (message->type == trialwire::Message::Built) {
            if (message->reply.built)
                emit built(message->reply.id);
            continue;
        }
        if (message->type != trialwire::Message::Result)
            continue;
        m_deadline.stop();
        m_silentDeaths = 0;
        m_inFlight.reset();
        answer(message->reply.id, message->reply.built ? Outcome::Tried : Outcome::NotBuilt,
               message->reply.result, message->reply.diagnostics);
    }
    sendNext();
}

void TrialProcess::timedOut()
{
    QProcess *stuck = m_process;
    m_process = nullptr; // its end (helperEnded) only deletes it now
    if (stuck)
        stuck->kill();
    refuseInFlight(tr("compiling this program and drawing it on small frames did not finish "
                      "within %1 (the trial's helper was replaced): an endless or very long "
                      "loop, or a program too big for the driver?")
                       .arg(durationText(m_limitMs)));
    startHelper(); // warm for the next edit
    sendNext();
}

void TrialProcess::helperEnded(QProcess *process)
{
    process->deleteLater();
    if (process != m_process)
        return; // replaced already
    m_process = nullptr;
    const bool crashed =
        process->exitStatus() == QProcess::CrashExit || process->error() == QProcess::FailedToStart;
    const QString why = QString::fromLocal8Bit(m_stderr).trimmed();
    m_stderr.clear();
    // Ended with no trial running: it could not start. Ended during one: the program did it.
    const bool silent = !m_inFlight && ++m_silentDeaths >= kMaxSilentDeaths;
    if (process->error() == QProcess::FailedToStart ||
        (!crashed && process->exitCode() == trialwire::kExitCannotDraw) || silent) {
        // No helper, or one that cannot draw: the window tries programs itself from now on.
        qWarning("lightbench: the trial helper %s cannot try programs (%s); the window tries "
                 "them itself",
                 qPrintable(helperPath()),
                 qPrintable(why.isEmpty() ? process->errorString() : why));
        m_available = false;
        m_deadline.stop();
        if (m_inFlight) {
            const quint64 id = m_inFlight->request.id;
            m_inFlight.reset();
            answer(id, Outcome::Unavailable);
        }
        sendNext();
        return;
    }
    m_deadline.stop();
    if (!crashed && process->exitCode() == trialwire::kExitOutOfMemory) {
        char limit[32];
        refuseInFlight(tr("the driver ran out of memory compiling or drawing this program "
                          "(limit %1; the trial's helper was replaced)")
                           .arg(memoryText(programMemoryKB(), limit)));
        sendNext();
        return;
    }
    refuseInFlight(crashed ? tr("the driver crashed the trial's helper while it drew this "
                                "program (it was replaced)")
                           : tr("the trial's helper ended while it drew this program (exit code "
                                "%1; it was replaced)")
                                 .arg(process->exitCode()));
    sendNext();
}

void TrialProcess::refuseInFlight(const QString &why)
{
    if (!m_inFlight)
        return;
    const Pending tried = std::move(*m_inFlight);
    m_inFlight.reset();
    TrialResult result;
    result.refusal = refusalAt(tried.request.vertex, tried.request.fragment, why);
    answer(tried.request.id, Outcome::Tried, result);
}

void TrialProcess::answer(quint64 id, Outcome outcome, const TrialResult &result,
                          const std::vector<Diagnostic> &diagnostics)
{
    // From the event loop, never from inside tryProgram(): the caller may be half-way
    // through its own state (the window builds its candidate around the call).
    QMetaObject::invokeMethod(
        this,
        [this, id, outcome, result, diagnostics] {
            emit finished(id, outcome, result, diagnostics);
        },
        Qt::QueuedConnection);
}

} // namespace lb
