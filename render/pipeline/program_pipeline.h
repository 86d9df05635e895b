#pragma once
// A user's program's life in the window, from the editor's text to "drawing": tried in the
// trial helper first (compiled, linked and drawn on small frames under its bounds; the window
// never waits), built in the window's context meanwhile and adopted once the helper accepts
// it, or refused with a reason on a line; the last good program keeps drawing throughout.
// Also: tried in the window's own context when there is no helper, built again in a new
// context, refused when the context is lost while it draws or when the view grows past what
// its trial allows, tried again once an object arrives. GL-free: the viewport is its host
// (a place to build, a way to time a frame: WindowProgramHost) and shows what it says.

#include "program_host.h"
#include "program_trial.h"
#include "trial_process.h"

#include <QObject>

#include <memory>
#include <optional>

namespace lb {

struct Mesh;
struct Scene;

// The window's context, as the pipeline needs it beyond building and timing.
class WindowProgramHost : public ProgramHost
{
public:
    virtual bool hasContext() const = 0;
    virtual bool hasObject() const = 0;   // something to time (a mesh still loading: no)
    virtual QSize viewPixels() const = 0; // the frame drawn, in device pixels
    virtual const Scene &scene() const = 0;
    virtual std::shared_ptr<const Mesh> objectMesh() const = 0;
    virtual bool drawsUserProgram() const = 0;
    virtual void useBuiltIn() = 0; // the built-in programs draw again
    // A program built aside, not drawn until adopted (Renderer::buildCandidate).
    virtual ProgramBuild buildCandidate(const ProgramSources &sources) = 0;
    virtual bool hasCandidate() const = 0;
    virtual void prepareCandidate() = 0; // its code generated ahead of its first frame
    virtual void adoptCandidate() = 0;
    virtual void dropCandidate() = 0;
    // The context is gone (the driver reset it): the handles go and a new one is made, in
    // which contextReady() builds the good program again.
    virtual void renewContext() = 0;
};

class ProgramPipeline : public QObject
{
    Q_OBJECT
public:
    // Where a program that is not ours is tried: in the trial helper (the default), in the
    // window's own context (when there is no helper), or not at all (for the benchmark's
    // comparison only). $LIGHTBENCH_PROGRAM_TRIAL=helper|window|off.
    enum class TrialMode { Helper, Window, Off };

    explicit ProgramPipeline(WindowProgramHost *host, QObject *parent = nullptr);

    // A program from the editor: built now, or once the context exists, and answered by
    // built() (at once, or when the helper has tried it).
    void submit(const ProgramSources &sources);
    // The host has a (new) context: the program asked for before it, or the good one, is
    // built in it.
    void contextReady();
    // The driver lost the context while the program drew: it is refused, the one before it
    // comes back in a new context.
    void contextLost();
    // The view's size changed: a program tried at the old size that would be too slow at the
    // new one is refused before it draws a frame there.
    void viewResized();
    // An object arrived: a program tried on an empty view is tried again on it.
    void objectArrived();
    // Side B's program (an exercise's reference, from files someone handed out) tried in a
    // helper of its own and waited for: the failed build when it does not build or is refused
    // there; nothing when it may be built in the window.
    std::optional<ProgramBuild> refusalOfSideB(const ProgramSources &sources);

    // Why the program drawing may not draw a frame of `pixels` (its trial's estimate is over
    // the budget there); empty when it may.
    QString tooSlowAt(QSize pixels) const;
    const std::optional<TrialResult> &drawingTrial() const { return m_goodTrial; }
    bool isTrying() const { return m_candidate.has_value(); }
    void setFrameBudget(double milliseconds) { m_frameBudgetMs = milliseconds; }
    double frameBudget() const { return m_frameBudgetMs; }
    void setTrialMode(TrialMode mode) { m_trialMode = mode; }
    TrialProcess *trialProcess() const { return m_trialProcess; }

signals:
    // What the last program asked for came to: drawing (`why` empty, `failed` false), or not
    // drawing because it did not build (`why` empty) or was refused (`why`), while
    // `builtInDrawing` says what draws instead. Then built() with its diagnostics.
    void stateChanged(bool failed, const QString &why, bool builtInDrawing);
    void built(const lb::ProgramBuild &build);

private:
    void buildNow(const ProgramSources &sources, bool tryHere = false);
    void candidateBuilt(quint64 id);
    void trialFinished(quint64 id, TrialProcess::Outcome outcome, const TrialResult &result,
                       const std::vector<Diagnostic> &diagnostics);
    void finish(const ProgramBuild &build, const QString &refused, const ProgramSources &sources,
                const std::optional<TrialResult> &trial);
    // The program drawing is refused for `why`: the good one before it comes back (in this
    // context, or in a new one when `newContext`).
    void refuseDrawing(const QString &why, bool newContext);
    trialwire::TryRequest request(const ProgramSources &sources);

    WindowProgramHost *m_host;
    TrialProcess *m_trialProcess;
    TrialProcess *m_sideBTrial = nullptr; // side B's, started when side B first needs it
    TrialMode m_trialMode = TrialMode::Helper;
    double m_frameBudgetMs = 1000.0;
    // The program the helper is trying: built in the window once the helper built it
    // (build), drawn once the helper accepted it.
    struct Candidate
    {
        quint64 id;
        ProgramSources sources;
        std::optional<ProgramBuild> build;
    };
    std::optional<Candidate> m_candidate;
    quint64 m_lastTrialId = 0;
    bool m_trialWithoutObject = false; // the program was tried before there was an object
    bool m_recovering = false;
    // The last sources that linked (built again in a new context), the good ones before them
    // (empty: the built-in program), and what their trials measured (none: not tried, no
    // loop), for a bigger frame later.
    ProgramSources m_good, m_previous;
    std::optional<TrialResult> m_goodTrial, m_previousTrial;
    std::optional<ProgramSources> m_pending; // asked for before there was a context
};

} // namespace lb
