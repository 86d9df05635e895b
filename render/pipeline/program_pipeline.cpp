#include "program_pipeline.h"

#include "loops.h"
#include "presets.h"
#include "program_route.h"
#include "scene.h"

#include <QCoreApplication>

namespace lb {

namespace {
// A vertex stage whose loops are all counted and this short (the built-in Gouraud's four
// lights) may run before its trial answers: a million vertices would take well under a second.
constexpr int kShortLoopSteps = 64;
} // namespace

ProgramPipeline::ProgramPipeline(WindowProgramHost *host, QObject *parent)
    : QObject(parent), m_host(host), m_trialProcess(new TrialProcess(this))
{
    connect(m_trialProcess, &TrialProcess::built, this, &ProgramPipeline::candidateBuilt);
    connect(m_trialProcess, &TrialProcess::finished, this, &ProgramPipeline::trialFinished);
    const QString mode = qEnvironmentVariable("LIGHTBENCH_PROGRAM_TRIAL");
    m_trialMode = mode == "off"      ? TrialMode::Off
                  : mode == "window" ? TrialMode::Window
                                     : TrialMode::Helper;
}

void ProgramPipeline::submit(const ProgramSources &sources)
{
    if (!m_host->hasContext()) {
        m_pending = sources;
        return;
    }
    buildNow(sources);
}

void ProgramPipeline::contextReady()
{
    if (m_pending)
        buildNow(*m_pending);
    else if (!m_good.isEmpty())
        m_host->use(m_good);
    m_pending.reset();
}

void ProgramPipeline::contextLost()
{
    if (m_recovering)
        return;
    m_recovering = true;
    // The window's words keep the viewport's translation context, where they were first written.
    refuseDrawing(QCoreApplication::translate(
                      "lb::Viewport", "the OpenGL context was lost while this program drew (the "
                                      "driver reset the GPU: an endless or very long loop?)"),
                  true);
    m_recovering = false;
}

void ProgramPipeline::viewResized()
{
    if (const QString why = tooSlowAt(m_host->viewPixels()); !why.isEmpty())
        refuseDrawing(why, false);
}

void ProgramPipeline::objectArrived()
{
    if (!m_trialWithoutObject || !m_host->hasObject() || !m_host->hasContext())
        return;
    // The program was tried on an empty view: tried again on the object, as if new.
    if (m_candidate) {
        const ProgramSources waiting = m_candidate->sources; // buildNow() drops it
        buildNow(waiting);
    } else if (m_host->drawsUserProgram()) {
        m_host->useBuiltIn();
        buildNow(m_good);
    }
}

void ProgramPipeline::refuseDrawing(const QString &why, bool newContext)
{
    const ProgramSources refused = m_good;
    m_good = m_previous;
    m_goodTrial = m_previousTrial;
    m_previous = {};
    m_previousTrial.reset();
    m_candidate.reset();
    if (newContext)
        m_host->renewContext(); // contextReady() builds the good program in the new one
    else if (m_host->hasContext()) {
        if (m_good.isEmpty())
            m_host->useBuiltIn();
        else
            m_host->use(m_good);
    }
    emit stateChanged(true, why, m_good.isEmpty());
    if (!refused.isEmpty()) {
        ProgramBuild build;
        build.diagnostics.push_back(refusalAt(refused.vertex, refused.fragment, why));
        emit built(build);
    }
}

QString ProgramPipeline::tooSlowAt(QSize pixels) const
{
    const double area = double(pixels.width()) * pixels.height();
    if (!m_goodTrial || !m_host->drawsUserProgram() ||
        !m_goodTrial->overBudgetAt(area, m_frameBudgetMs))
        return {};
    return slowFrameMessage(pixels, m_frameBudgetMs, m_good.vertex, m_good.fragment);
}

trialwire::TryRequest ProgramPipeline::request(const ProgramSources &sources)
{
    trialwire::TryRequest request;
    request.id = ++m_lastTrialId;
    request.scene = m_host->scene().toJson();
    request.vertex = sources.vertex;
    request.fragment = sources.fragment;
    request.target = m_host->viewPixels();
    request.budgetMs = m_frameBudgetMs;
    return request;
}

void ProgramPipeline::buildNow(const ProgramSources &sources, bool tryHere)
{
    // Tried on small frames before it is adopted (program_trial.h): a program that would take
    // longer than the budget per frame at this view's size is refused, instead of freezing
    // the window for every frame it draws.
    const QSize target = m_host->viewPixels();
    // With no object yet (a mesh file still loading) the trial would time the background:
    // it runs again once the object is there (objectArrived).
    m_trialWithoutObject = !m_host->hasObject();
    m_candidate.reset(); // a trial still running answers for a program no longer wanted
    m_host->dropCandidate();
    // The presets as shipped are ours and draw in good time: drawn at once, untried (the
    // built-in program follows the shading switch without a trial's delay).
    const bool ours = isPresetProgram(sources.vertex, sources.fragment);
    if (!ours && !tryHere && m_trialMode == TrialMode::Helper && m_trialProcess->isAvailable()) {
        // Every other program is compiled, linked and drawn in the helper first, under its
        // memory bound and the trial's time limit: the driver's compiler is never given a
        // stranger's program in the window's process (a macro bomb took one to 24 GB). The
        // helper's answer (trialFinished) brings the diagnostics; only an accepted program
        // is built here (from the moment the helper built it: candidateBuilt). Meanwhile the
        // last good program keeps drawing.
        const trialwire::TryRequest tried = request(sources);
        m_candidate = Candidate{tried.id, sources, std::nullopt};
        m_trialProcess->tryProgram(tried, m_host->objectMesh());
        return;
    }
    QString refused;
    std::optional<TrialResult> measured; // none: nothing was drawn to time it
    const auto trial = [&]() -> std::optional<Diagnostic> {
        const TrialResult result = tryIn(*m_host, sources, {target, m_frameBudgetMs, kWindowTrial});
        if (result.refusal)
            refused = result.refusal->message;
        else
            measured = result;
        return result.refusal;
    };
    const ProgramBuild build =
        m_trialMode == TrialMode::Off || ours ? m_host->use(sources) : m_host->use(sources, trial);
    finish(build, refused, sources, measured);
}

void ProgramPipeline::candidateBuilt(quint64 id)
{
    if (!m_candidate || m_candidate->id != id || !m_host->hasContext())
        return;
    // The helper's driver compiled and linked it within its bounds: built here too while the
    // helper draws its trial frames, and the driver may generate its code here meanwhile (a
    // frame with nothing rasterized), so the first frame after the answer does not; only when
    // the vertex stage, which does run, has no loop to be slow in (or only short counted ones).
    m_candidate->build = m_host->buildCandidate(m_candidate->sources);
    if (m_candidate->build->ok() &&
        onlyShortLoops(m_candidate->sources.vertex, kShortLoopSteps, ShaderStage::Vertex))
        m_host->prepareCandidate();
}

void ProgramPipeline::trialFinished(quint64 id, TrialProcess::Outcome outcome,
                                    const TrialResult &result,
                                    const std::vector<Diagnostic> &diagnostics)
{
    if (!m_candidate || m_candidate->id != id || !m_host->hasContext())
        return; // a newer program is being tried, or there is no context to draw it in
    const Candidate tried = std::move(*m_candidate);
    m_candidate.reset();
    if (outcome == TrialProcess::Outcome::Unavailable) {
        buildNow(tried.sources, true); // no helper to try it: tried here, as before there was one
        return;
    }
    ProgramBuild build;
    build.diagnostics = diagnostics;
    QString refused;
    if (outcome == TrialProcess::Outcome::NotBuilt) {
        m_host->dropCandidate();
    } else if (result.refusal) {
        m_host->dropCandidate();
        build.diagnostics.push_back(*result.refusal);
        refused = result.refusal->message;
    } else if (m_host->hasCandidate()) {
        // Accepted: the helper's driver built and drew it within its bounds.
        m_host->adoptCandidate();
        build = *tried.build;
    } else {
        build = m_host->use(tried.sources); // a new context since
    }
    finish(build, refused, tried.sources,
           outcome == TrialProcess::Outcome::Tried && !result.refusal
               ? std::optional<TrialResult>(result)
               : std::nullopt);
}

void ProgramPipeline::finish(const ProgramBuild &build, const QString &refused,
                             const ProgramSources &sources, const std::optional<TrialResult> &trial)
{
    if (build.ok()) {
        if (sources != m_good) {
            m_previous = m_good;
            m_previousTrial = m_goodTrial;
        }
        m_good = sources;
        m_goodTrial = trial;
        emit stateChanged(false, {}, false);
    } else {
        // No reason given: it did not build.
        emit stateChanged(true, refused, !m_host->drawsUserProgram());
    }
    emit built(build);
}

std::optional<ProgramBuild> ProgramPipeline::refusalOfSideB(const ProgramSources &sources)
{
    // Side B's program comes from files or an exercise someone handed out: compiled and
    // drawn in a helper of its own first, as the editor's is (buildNow), and waited for (the
    // caller says at once whether it builds). Its own helper: side A's trial goes on.
    if (m_trialMode != TrialMode::Helper || isPresetProgram(sources.vertex, sources.fragment))
        return std::nullopt; // ours, as shipped: untried
    if (!m_sideBTrial)
        m_sideBTrial = new TrialProcess(this);
    if (!m_sideBTrial->isAvailable())
        return std::nullopt;
    const TrialProcess::Answer answer =
        m_sideBTrial->tryAndWait(request(sources), m_host->objectMesh());
    if (answer.outcome == TrialProcess::Outcome::Unavailable ||
        (answer.outcome == TrialProcess::Outcome::Tried && !answer.result.refusal))
        return std::nullopt;
    ProgramBuild refused;
    refused.diagnostics = answer.diagnostics;
    if (answer.result.refusal)
        refused.diagnostics.push_back(*answer.result.refusal);
    return refused;
}

} // namespace lb
