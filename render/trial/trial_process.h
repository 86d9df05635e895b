#pragma once
// The workbench's end of the trial helper (lightbench-trial, trial_server.h): a process that
// stays up between edits with its OpenGL context warm and tries each new program on small
// frames (program_trial.h). The window never waits for it: the answer arrives as a signal,
// and meanwhile the last good program keeps drawing. A trial that takes longer than the
// limit (the driver hangs on the program) or kills the helper (the driver crashes, or resets
// the context) refuses the program, and a new helper takes the old one's place.

#include "trial_wire.h"

#include <QObject>
#include <QPointer>
#include <QProcess>
#include <QTimer>

#include <memory>
#include <vector>

namespace lb {

class TrialProcess : public QObject
{
    Q_OBJECT
public:
    enum class Outcome {
        Tried,      // `result` says whether the program is refused
        NotBuilt,   // it did not compile or link: the diagnostics say why
        Unavailable // there is no helper, or it cannot draw: the caller tries it itself
    };

    explicit TrialProcess(QObject *parent = nullptr);
    ~TrialProcess() override;

    // Tries a program on `mesh` (sent to the helper when it is not the last one sent).
    // finished() follows with the request's id, unless a newer request replaces this one
    // before the helper takes it (only the newest waiting request is kept).
    void tryProgram(const trialwire::TryRequest &request, std::shared_ptr<const Mesh> mesh);
    // The same, waited for: for what must answer at once (side B's program, chosen in a
    // dialog). The window keeps repainting meanwhile and holds the user's input back; the
    // limit bounds the wait.
    struct Answer
    {
        Outcome outcome = Outcome::Unavailable;
        TrialResult result;
        std::vector<Diagnostic> diagnostics;
    };
    Answer tryAndWait(const trialwire::TryRequest &request, std::shared_ptr<const Mesh> mesh);
    // How long one trial may take, the helper's start included.
    void setLimit(int milliseconds) { m_limitMs = milliseconds; }
    qint64 helperPid() const;
    // False once the helper could not start or could not draw; then every trial answers
    // Unavailable.
    bool isAvailable() const { return m_available; }

    // $LIGHTBENCH_TRIAL_HELPER, else lightbench-trial beside the executable, in the installed
    // libexec folder or on the PATH (helper_program.h).
    static QString helperPath();

signals:
    // The program of request `id` compiled and linked in the helper (within its bounds); its
    // trial's frames follow, then finished().
    void built(quint64 id);
    // `diagnostics`: the helper's build's (Tried, NotBuilt), errors and warnings alike.
    void finished(quint64 id, lb::TrialProcess::Outcome outcome, const lb::TrialResult &result,
                  const std::vector<lb::Diagnostic> &diagnostics);

private:
    struct Pending
    {
        trialwire::TryRequest request;
        std::shared_ptr<const Mesh> mesh;
    };
    void startHelper();
    void send(const Pending &pending);
    void sendNext();
    void readOutput();
    void helperEnded(QProcess *process);
    void timedOut();
    void answer(quint64 id, Outcome outcome, const TrialResult &result = {},
                const std::vector<Diagnostic> &diagnostics = {});
    void refuseInFlight(const QString &why);

    QPointer<QProcess> m_process;
    QByteArray m_output;
    QByteArray m_stderr;
    QTimer m_deadline;
    std::optional<Pending> m_inFlight, m_waiting;
    std::weak_ptr<const Mesh> m_sentMesh; // what the current helper draws
    bool m_meshSent = false;
    bool m_available = true;
    int m_silentDeaths = 0; // helpers that ended before answering, in a row
    int m_limitMs = 4000;
};

} // namespace lb

Q_DECLARE_METATYPE(lb::TrialResult)
Q_DECLARE_METATYPE(lb::TrialProcess::Outcome)
