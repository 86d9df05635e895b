#include "viewport.h"

#include "difference_scale_labels.h"

#include "loops.h"
#include "presets.h"
#include "program_trial.h"
#include "webgl1_translation.h"

#include <QCoreApplication>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
constexpr float kDegreesPerPixel = 0.4f;
constexpr float kAutoRotateDegreesPerSecond = 30.0f;
// A vertex stage whose loops are all counted and this short (the built-in Gouraud's four
// lights) may run before its trial answers: a million vertices would take well under a second.
constexpr int kShortLoopSteps = 64;
} // namespace

Viewport::Viewport(SceneDocument *document, QWidget *parent)
    : QOpenGLWidget(parent), m_document(document)
{
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true); // the cursor changes over the wipe's line
    setToolTip(tr("Left drag: orbit - right or middle drag: pan - wheel: zoom - R: reset view"));
    connect(document, &SceneDocument::changed, this, [this] {
        syncAnimation();
        update();
    });
    // A child widget over the GL picture: Qt composes it, and its text is drawn by the raster
    // engine, so it stays crisp and appears in window grabs.
    m_banner = new QLabel(this);
    m_banner->setStyleSheet("QLabel { background: rgba(120, 20, 20, 200); color: white; "
                            "padding: 4px 8px; }");
    m_banner->setWordWrap(true); // the whole message also over a narrow view
    m_banner->hide();
    m_compareLabel = new QLabel(this);
    m_compareLabel->setStyleSheet("QLabel { background: rgba(0, 0, 0, 170); color: white; "
                                  "padding: 3px 6px; }");
    m_compareLabel->hide();
    m_labels = new ProbeLabels(document, this);
    m_differenceLabels = new DifferenceScaleLabels(this);
    m_trialProcess = new TrialProcess(this);
    connect(m_trialProcess, &TrialProcess::built, this, &Viewport::candidateBuilt);
    connect(m_trialProcess, &TrialProcess::finished, this, &Viewport::trialFinished);
    const QString mode = qEnvironmentVariable("LIGHTBENCH_PROGRAM_TRIAL");
    m_trialMode = mode == "off"      ? TrialMode::Off
                  : mode == "window" ? TrialMode::Window
                                     : TrialMode::Helper;
    m_animation.setInterval(16);
    connect(&m_animation, &QTimer::timeout, this, &Viewport::advanceAnimation);
    syncAnimation();
}

Viewport::~Viewport()
{
    // The base class destroys the context after this body has run; by then the renderer is
    // gone, so the context must not call back into releaseGl().
    if (context())
        disconnect(context(), nullptr, this, nullptr);
    releaseGl();
}

void Viewport::releaseGl()
{
    makeCurrent();
    m_renderer.cleanup();
    doneCurrent();
}

void Viewport::initializeGL()
{
    // A reparented viewport gets a new context: drop what belonged to the old one first.
    m_renderer.cleanup();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl,
            Qt::UniqueConnection);
    m_resetStatus.attach(context());
    m_error = m_renderer.initialize();
    if (m_error.isEmpty()) {
        if (m_pending)
            buildNow(m_pendingVertex, m_pendingFragment);
        else if (!m_goodVertex.isEmpty())
            m_renderer.setUserProgram(m_goodVertex, m_goodFragment);
        m_pending = false;
        if (!m_sideBVertex.isEmpty())
            m_renderer.setSideBProgram(m_sideBVertex, m_sideBFragment);
    }
    const QSurfaceFormat f = context()->format();
    auto *gl = context()->functions();
    emit glInfo(driverText(QString("%1.%2").arg(f.majorVersion()).arg(f.minorVersion()),
                           reinterpret_cast<const char *>(gl->glGetString(GL_RENDERER)),
                           translatesWebGl1()));
}

void Viewport::paintEvent(QPaintEvent *event)
{
    if (context() && !context()->isValid()) { // lost since the last frame
        recoverLostContext();
        return;
    }
    QOpenGLWidget::paintEvent(event);
}

void Viewport::recoverLostContext()
{
    if (m_recovering)
        return;
    m_recovering = true;
    refuseDrawingProgram(tr("the OpenGL context was lost while this program drew (the driver "
                            "reset the GPU: an endless or very long loop?)"),
                         true);
    m_recovering = false;
}

void Viewport::refuseDrawingProgram(const QString &why, bool newContext)
{
    const QString vertex = m_goodVertex, fragment = m_goodFragment;
    m_goodVertex = m_previousVertex;
    m_goodFragment = m_previousFragment;
    m_goodTrial = m_previousTrial;
    m_previousVertex.clear();
    m_previousFragment.clear();
    m_previousTrial.reset();
    m_candidate.reset();
    if (newContext) {
        m_renderer.cleanup(); // the objects died with the context: only the handles go
        // What a reparented widget gets: QOpenGLWidget drops its context and makes a new
        // one, and initializeGL() builds the good program in it.
        QEvent windowChange(QEvent::WindowChangeInternal);
        QCoreApplication::sendEvent(this, &windowChange);
    } else if (m_renderer.isInitialized()) {
        makeCurrent();
        if (m_goodVertex.isEmpty())
            m_renderer.clearUserProgram();
        else
            m_renderer.setUserProgram(m_goodVertex, m_goodFragment);
        doneCurrent();
    }
    setBanner(bannerText(why, m_goodVertex.isEmpty()));
    update();
    if (!vertex.isEmpty()) {
        ProgramBuild refused;
        refused.diagnostics.push_back(refusalAt(vertex, fragment, why));
        emit programBuilt(refused);
    }
}

QString Viewport::tooSlowAt(QSize pixels) const
{
    if (!m_goodTrial || !m_renderer.hasUserProgram() ||
        !m_goodTrial->overBudgetAt(double(pixels.width()) * pixels.height(), m_frameBudgetMs))
        return {};
    //: %1 a duration (0.8 s); %2x%3 the view's size in pixels; %4 the frame budget
    return tr("drawing one frame with this program would take about %1 at %2x%3 (the budget "
              "is %4): an endless or very long loop?")
        .arg(durationText(m_goodTrial->estimateAt(double(pixels.width()) * pixels.height())))
        .arg(pixels.width())
        .arg(pixels.height())
        .arg(durationText(m_frameBudgetMs));
}

void Viewport::paintGL()
{
    if (!m_error.isEmpty()) {
        QPainter painter(this);
        painter.fillRect(rect(), Qt::black);
        painter.setPen(Qt::white);
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::TextWordWrap,
                         tr("The renderer could not start:\n%1").arg(m_error));
        return;
    }
    m_renderer.render(m_document->scene(), size() * devicePixelRatio());
    if (m_resetStatus.wasReset()) {
        QTimer::singleShot(0, this, &Viewport::recoverLostContext);
        return;
    }
    updateCompareLabel();
    if (m_labels->isVisible())
        m_labels->update(); // the names follow the camera and the light
}

void Viewport::setProbe(std::vector<Renderer::Arrow> arrows, QPoint pixel,
                        std::vector<ProbeLabel> labels, bool againstSideB)
{
    m_renderer.setProbe(std::move(arrows), pixel);
    m_renderer.setProbeAgainstSideB(againstSideB);
    m_labels->setLabels(std::move(labels));
    update();
}

bool Viewport::nearWipe(QPoint position) const
{
    const Scene &s = m_document->scene();
    if (s.compare.mode != CompareMode::Wipe)
        return false;
    return std::abs(position.x() - int(std::lround(s.compare.wipe * float(width())))) <= 6;
}

void Viewport::compileProgram(const QString &vertexSource, const QString &fragmentSource)
{
    if (!m_renderer.isInitialized()) {
        m_pendingVertex = vertexSource;
        m_pendingFragment = fragmentSource;
        m_pending = true;
        return;
    }
    makeCurrent();
    buildNow(vertexSource, fragmentSource);
    doneCurrent();
}

double Viewport::rawBuildMilliseconds(const QString &vertexSource, const QString &fragmentSource,
                                      bool draw)
{
    makeCurrent();
    const double ms =
        lb::rawBuildMilliseconds(*context()->extraFunctions(), vertexSource, fragmentSource, draw);
    doneCurrent();
    return ms;
}

void Viewport::buildNow(const QString &vertexSource, const QString &fragmentSource, bool tryHere)
{
    // Tried on small frames before it is adopted (program_trial.h): a program that would take
    // longer than the budget per frame at this view's size is refused, instead of freezing
    // the window for every frame it draws.
    const QSize target = size() * devicePixelRatio();
    // With no object yet (a mesh file still loading) the trial would time the background:
    // it runs again once the object is there (setObject).
    m_trialWithoutObject = !m_renderer.objectMesh();
    m_candidate.reset(); // a trial still running answers for a program no longer wanted
    m_renderer.dropCandidate();
    // The presets as shipped are ours and draw in good time: drawn at once, untried (the
    // built-in program follows the shading switch without a trial's delay).
    const bool ours = isPresetProgram(vertexSource, fragmentSource);
    if (!ours && !tryHere && m_trialMode == TrialMode::Helper && m_trialProcess->isAvailable()) {
        // Every other program is compiled, linked and drawn in the helper first, under its
        // memory bound and the trial's time limit: the driver's compiler is never given a
        // stranger's program in the window's process (a macro bomb took one to 24 GB). The
        // helper's answer (trialFinished) brings the diagnostics; only an accepted program
        // is built here (from the moment the helper built it: candidateBuilt). Meanwhile the
        // last good program keeps drawing.
        m_candidate = Candidate{++m_lastTrialId, vertexSource, fragmentSource, std::nullopt};
        trialwire::TryRequest request;
        request.id = m_candidate->id;
        request.scene = m_document->scene().toJson();
        request.vertex = vertexSource;
        request.fragment = fragmentSource;
        request.target = target;
        request.budgetMs = m_frameBudgetMs;
        m_trialProcess->tryProgram(request, m_renderer.sharedObjectMesh());
        return;
    }
    QString refused;
    std::optional<TrialResult> measured; // none: nothing was drawn to time it
    const auto trial = [&]() -> std::optional<Diagnostic> {
        const TrialResult result = tryProgram(
            vertexSource, fragmentSource, target, m_frameBudgetMs, kWindowTrial,
            [this](QSize pixels) { return timeFrame(pixels); },
            [this](QSize pixels) {
                return m_renderer.withBuiltIn([&] { return timeFrame(pixels); });
            });
        if (result.refusal)
            refused = result.refusal->message;
        else
            measured = result;
        return result.refusal;
    };
    const ProgramBuild build = m_trialMode == TrialMode::Off || ours
                                   ? m_renderer.setUserProgram(vertexSource, fragmentSource)
                                   : m_renderer.setUserProgram(vertexSource, fragmentSource, trial);
    finishBuild(build, refused, vertexSource, fragmentSource, measured);
}

void Viewport::candidateBuilt(quint64 id)
{
    if (!m_candidate || m_candidate->id != id || !m_renderer.isInitialized())
        return;
    // The helper's driver compiled and linked it within its bounds: built here too while the
    // helper draws its trial frames, and the driver may generate its code here meanwhile (a
    // frame with nothing rasterized), so the first frame after the answer does not; only when
    // the vertex stage, which does run, has no loop to be slow in (or only short counted ones).
    makeCurrent();
    m_candidate->build = m_renderer.buildCandidate(m_candidate->vertex, m_candidate->fragment);
    if (m_candidate->build->ok() && onlyShortLoops(m_candidate->vertex, kShortLoopSteps))
        prepareCandidate();
    doneCurrent();
}

void Viewport::trialFinished(quint64 id, TrialProcess::Outcome outcome, const TrialResult &result,
                             const std::vector<Diagnostic> &diagnostics)
{
    if (!m_candidate || m_candidate->id != id || !m_renderer.isInitialized())
        return; // a newer program is being tried, or there is no context to draw it in
    const Candidate tried = std::move(*m_candidate);
    m_candidate.reset();
    makeCurrent();
    if (outcome == TrialProcess::Outcome::Unavailable) {
        // No helper to try it: tried here, as before there was one.
        buildNow(tried.vertex, tried.fragment, true);
        doneCurrent();
        return;
    }
    ProgramBuild build;
    build.diagnostics = diagnostics;
    QString refused;
    if (outcome == TrialProcess::Outcome::NotBuilt) {
        m_renderer.dropCandidate();
    } else if (result.refusal) {
        m_renderer.dropCandidate();
        build.diagnostics.push_back(*result.refusal);
        refused = result.refusal->message;
    } else if (m_renderer.hasCandidate()) {
        // Accepted: the helper's driver built and drew it within its bounds.
        m_renderer.adoptCandidate();
        build = *tried.build;
    } else {
        build = m_renderer.setUserProgram(tried.vertex, tried.fragment); // a new context since
    }
    doneCurrent();
    finishBuild(build, refused, tried.vertex, tried.fragment,
                outcome == TrialProcess::Outcome::Tried && !result.refusal
                    ? std::optional<TrialResult>(result)
                    : std::nullopt);
}

void Viewport::finishBuild(const ProgramBuild &build, const QString &refused,
                           const QString &vertexSource, const QString &fragmentSource,
                           const std::optional<TrialResult> &trial)
{
    const bool builtInDrawing = !m_renderer.hasUserProgram();
    if (build.ok()) {
        if (vertexSource != m_goodVertex || fragmentSource != m_goodFragment) {
            m_previousVertex = m_goodVertex;
            m_previousFragment = m_goodFragment;
            m_previousTrial = m_goodTrial;
        }
        m_goodVertex = vertexSource;
        m_goodFragment = fragmentSource;
        m_goodTrial = trial;
        setBanner({});
    } else {
        setBanner(bannerText(refused, builtInDrawing)); // no reason given: it did not build
    }
    update();
    emit programBuilt(build);
}

namespace {
// The attachments of the widget's own framebuffer: a driver that generates code per
// framebuffer format (llvmpipe) then reuses what a trial or a preparation generated for the
// frame on screen.
QOpenGLFramebufferObjectFormat widgetFormat()
{
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    return format;
}
} // namespace

void Viewport::prepareCandidate()
{
    QOpenGLFramebufferObject fbo(QSize(4, 4), widgetFormat());
    if (!fbo.isValid())
        return;
    fbo.bind();
    m_renderer.prepareCandidate(m_document->scene(), fbo.size());
    fbo.release();
}

double Viewport::timeFrame(QSize pixels)
{
    QOpenGLFramebufferObject fbo(pixels, widgetFormat());
    if (!fbo.isValid())
        return 0.0;
    fbo.bind();
    QElapsedTimer clock;
    clock.start();
    m_renderer.render(m_document->scene(), pixels);
    context()->functions()->glFinish();
    const double ms = double(clock.nsecsElapsed()) * 1e-6;
    fbo.release();
    return ms;
}

QString Viewport::banner() const
{
    return m_banner->isVisible() ? m_banner->text() : QString();
}

void Viewport::setBanner(const QString &text)
{
    m_banner->setText(text);
    m_banner->setVisible(!text.isEmpty());
    m_banner->setGeometry(0, 0, width(), m_banner->heightForWidth(width()));
}

void Viewport::resizeGL(int, int)
{
    // A program tried at the view's old size may be too slow at the new one: refused before
    // it draws a frame there.
    if (const QString why = tooSlowAt(size() * devicePixelRatio()); !why.isEmpty())
        refuseDrawingProgram(why, false);
    m_banner->setGeometry(0, 0, width(), m_banner->heightForWidth(width()));
    updateCompareLabel();
    emit resized();
}

void Viewport::setObjectCount(int count)
{
    if (count == m_renderer.objectCount())
        return;
    // Fewer objects release GL buffers: the context must be current for that.
    const bool current = m_renderer.isInitialized() && count < m_renderer.objectCount();
    if (current)
        makeCurrent();
    m_renderer.setObjectCount(count);
    if (current)
        doneCurrent();
    update();
    emit objectChanged();
}

void Viewport::setObject(int index, std::shared_ptr<const Mesh> mesh,
                         std::shared_ptr<const Texture> texture)
{
    const bool changed = mesh.get() != m_renderer.objectMesh(index);
    const bool retextured = !changed && index < m_renderer.objectCount() &&
                            texture.get() != m_renderer.ownTexture(index);
    // Uploaded by the next paint.
    m_renderer.setObject(index, std::move(mesh), std::move(texture));
    if (m_trialWithoutObject && m_renderer.objectMesh() && m_renderer.isInitialized()) {
        // The program was tried on an empty view: tried again on the object, as if new.
        makeCurrent();
        if (m_candidate) {
            const Candidate waiting = *m_candidate; // buildNow() drops it
            buildNow(waiting.vertex, waiting.fragment);
        } else if (m_renderer.hasUserProgram()) {
            m_renderer.clearUserProgram();
            buildNow(m_goodVertex, m_goodFragment);
        }
        doneCurrent();
    }
    update();
    if (changed)
        emit objectChanged();
    else if (retextured)
        emit textureChanged();
}

ProgramBuild Viewport::setSideBProgram(const QString &vertexSource, const QString &fragmentSource,
                                       const QString &name)
{
    m_sideBVertex = vertexSource;
    m_sideBFragment = fragmentSource;
    m_sideBName = name;
    ProgramBuild build;
    build.linked = true;
    if (!vertexSource.isEmpty() && !isPresetProgram(vertexSource, fragmentSource))
        if (std::optional<ProgramBuild> refused = refusedInHelper(vertexSource, fragmentSource))
            build = *refused;
    if (build.ok() && m_renderer.isInitialized()) {
        makeCurrent();
        if (vertexSource.isEmpty())
            m_renderer.clearSideBProgram();
        else
            build = m_renderer.setSideBProgram(vertexSource, fragmentSource);
        doneCurrent();
    }
    if (!build.ok()) // the built-in program stays side B
        m_sideBVertex.clear(), m_sideBFragment.clear(), m_sideBName.clear();
    update();
    return build;
}

std::optional<ProgramBuild> Viewport::refusedInHelper(const QString &vertexSource,
                                                      const QString &fragmentSource)
{
    // Side B's program comes from files or an exercise someone handed out: compiled and
    // drawn in a helper of its own first, as the editor's is (buildNow), and waited for (the
    // caller says at once whether it builds). Its own helper: side A's trial goes on.
    if (m_trialMode != TrialMode::Helper)
        return std::nullopt;
    if (!m_sideBTrial)
        m_sideBTrial = new TrialProcess(this);
    if (!m_sideBTrial->isAvailable())
        return std::nullopt;
    trialwire::TryRequest request;
    request.id = ++m_lastTrialId;
    request.scene = m_document->scene().toJson();
    request.vertex = vertexSource;
    request.fragment = fragmentSource;
    request.target = size() * devicePixelRatio();
    request.budgetMs = m_frameBudgetMs;
    const TrialProcess::Answer answer =
        m_sideBTrial->tryAndWait(request, m_renderer.sharedObjectMesh());
    if (answer.outcome == TrialProcess::Outcome::Unavailable ||
        (answer.outcome == TrialProcess::Outcome::Tried && !answer.result.refusal))
        return std::nullopt;
    ProgramBuild refused;
    refused.diagnostics = answer.diagnostics;
    if (answer.result.refusal)
        refused.diagnostics.push_back(*answer.result.refusal);
    return refused;
}

QImage Viewport::renderImage(QSize pixels)
{
    if (!m_renderer.isInitialized() || pixels.isEmpty() || !tooSlowAt(pixels).isEmpty())
        return {};
    makeCurrent();
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::Depth);
    QOpenGLFramebufferObject fbo(pixels, format);
    QImage image;
    if (fbo.isValid()) {
        fbo.bind();
        m_renderer.render(m_document->scene(), pixels);
        image = fbo.toImage();
        fbo.release();
    }
    doneCurrent();
    if (!image.isNull() && !m_labels->labels().empty()) {
        // The names at the size they have on screen, relative to the frame's height.
        const double frameHeight = std::max(1.0, height() * devicePixelRatioF());
        const int size = int(std::lround(m_labels->pixelSize() * pixels.height() / frameHeight));
        QPainter painter(&image);
        paintProbeLabels(painter, m_labels->placed(pixels, size), size);
    }
    return image;
}

void Viewport::resetCamera()
{
    m_document->edit([](Scene &s) { frameScene(s); }); // every visible object in sight
}

void Viewport::mousePressEvent(QMouseEvent *event)
{
    m_lastMouse = event->position().toPoint();
    m_draggingWipe = event->button() == Qt::LeftButton && nearWipe(m_lastMouse);
    m_probing = event->button() == Qt::LeftButton && !m_draggingWipe &&
                (event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier));
    if (m_probing)
        emit probeRequested((event->position() * devicePixelRatio()).toPoint());
    const bool plain = event->button() == Qt::LeftButton && !m_probing && !m_draggingWipe;
    m_pressedAt = plain ? m_lastMouse : QPoint(-1, -1);
    setFocus();
}

void Viewport::mouseReleaseEvent(QMouseEvent *event)
{
    m_draggingWipe = false;
    m_probing = false;
    // A press and release a few pixels apart is a click (the camera hardly turned).
    const QPoint at = event->position().toPoint();
    if (event->button() == Qt::LeftButton && m_pressedAt.x() >= 0 &&
        (at - m_pressedAt).manhattanLength() <= 4)
        emit clicked((event->position() * devicePixelRatio()).toPoint());
    m_pressedAt = QPoint(-1, -1);
}

void Viewport::mouseMoveEvent(QMouseEvent *event)
{
    const QPoint now = event->position().toPoint();
    const QPoint delta = now - m_lastMouse;
    m_lastMouse = now;
    // The wipe's line follows the mouse while dragged; near it the cursor says so.
    setCursor(m_draggingWipe || nearWipe(now) ? Qt::SplitHCursor : Qt::ArrowCursor);
    if (m_probing) {
        emit probeRequested((event->position() * devicePixelRatio()).toPoint());
        return;
    }
    if (m_draggingWipe) {
        const float x = float(now.x()) / float(std::max(width(), 1));
        m_document->edit([&](Scene &s) { s.compare.wipe = std::clamp(x, 0.0f, 1.0f); });
        return;
    }
    if (event->buttons() & Qt::LeftButton) {
        m_document->edit([&](Scene &s) {
            s.camera.orbit(-kDegreesPerPixel * float(delta.x()),
                           kDegreesPerPixel * float(delta.y()));
        });
    } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
        const float h = float(std::max(height(), 1));
        const float aspect = float(std::max(width(), 1)) / h;
        m_document->edit(
            [&](Scene &s) { s.camera.pan(float(delta.x()) / h, float(delta.y()) / h, aspect); });
    }
}

void Viewport::wheelEvent(QWheelEvent *event)
{
    const float steps = float(event->angleDelta().y()) / 120.0f;
    m_document->edit([&](Scene &s) { s.camera.zoom(steps); });
}

void Viewport::syncAnimation()
{
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    const bool on = std::any_of(objects.begin(), objects.end(),
                                [](const ObjectSettings &o) { return o.autoRotate; });
    if (on && !m_animation.isActive()) {
        m_clock.start();
        m_animation.start();
    } else if (!on) {
        m_animation.stop();
    }
}

void Viewport::advanceAnimation()
{
    const float seconds = float(m_clock.restart()) / 1000.0f;
    m_document->edit([&](Scene &s) {
        for (ObjectSettings &o : s.objects)
            if (o.autoRotate) {
                float &y = o.rotationDegrees.y;
                y = std::fmod(y + kAutoRotateDegreesPerSecond * seconds, 360.0f);
            }
    });
}

} // namespace lb
