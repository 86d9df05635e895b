#include "viewport.h"

#include "difference_scale_labels.h"

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
} // namespace

Viewport::Viewport(SceneDocument *document, QWidget *parent)
    : QOpenGLWidget(parent), m_document(document)
{
    setMinimumSize(320, 240);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true); // the cursor changes over the wipe's line
    setToolTip(tr("Left drag: orbit - right or middle drag: pan - wheel: zoom - R: reset view"));
    connect(document, &SceneDocument::changed, this, [this](SceneParts parts) {
        if (parts.testFlag(ScenePart::Bindings) && !m_submitted.isEmpty())
            compileProgram(m_submitted.vertex, m_submitted.fragment);
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
    m_pipeline = new ProgramPipeline(this, this);
    connect(m_pipeline, &ProgramPipeline::stateChanged, this, &Viewport::showProgramState);
    connect(m_pipeline, &ProgramPipeline::built, this, [this](const ProgramBuild &build) {
        m_lastBuild = build;
        ++m_builds;
        // The first frame the new program draws is looked at: one that shows nothing adds a
        // warning to what the build said (showFrameLook).
        if (build.ok() && m_renderer.hasUserProgram())
            m_renderer.lookAtNextFrame();
        emit programBuilt(build);
    });
    m_animation.setInterval(16);
    connect(&m_animation, &QTimer::timeout, this, &Viewport::advanceAnimation);
    syncAnimation();
}

void Viewport::compileProgram(const QString &vertexSource, const QString &fragmentSource)
{
    m_submitted = {vertexSource, fragmentSource, m_document->scene().bindings};
    m_pipeline->submit(m_submitted);
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
        m_pipeline->contextReady();
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
    if (const std::optional<FrameLook> look = m_renderer.takeFrameLook())
        showFrameLook(*look);
}

void Viewport::showFrameLook(FrameLook look)
{
    if (look == FrameLook::Drawn || !m_lastBuild.ok())
        return;
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.stage = ShaderStage::Link;
    d.message = frameLookWarning(look);
    m_lastBuild.diagnostics.push_back(d);
    // Out of paintGL: the listeners may ask for another frame.
    QTimer::singleShot(0, this, [this, builds = m_builds] {
        if (builds == m_builds) // no newer build has been said meanwhile
            emit programBuilt(m_lastBuild);
    });
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

double Viewport::rawBuildMilliseconds(const QString &vertexSource, const QString &fragmentSource,
                                      bool draw)
{
    makeCurrent();
    const double ms =
        lb::rawBuildMilliseconds(*context()->extraFunctions(), vertexSource, fragmentSource, draw);
    doneCurrent();
    return ms;
}

QString Viewport::banner() const
{
    return m_banner->isVisible() ? m_banner->text() : QString();
}

void Viewport::showProgramState(bool failed, const QString &why, bool builtInDrawing)
{
    setBanner(failed ? bannerText(why, builtInDrawing) : QString());
    update();
}

void Viewport::setBanner(const QString &text)
{
    m_banner->setText(text);
    m_banner->setVisible(!text.isEmpty());
    m_banner->setGeometry(0, 0, width(), m_banner->heightForWidth(width()));
}

void Viewport::resizeGL(int, int)
{
    m_pipeline->viewResized();
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
    m_pipeline->objectArrived(); // a program tried on an empty view: tried again
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
    if (!vertexSource.isEmpty())
        if (std::optional<ProgramBuild> refused =
                m_pipeline->refusalOfSideB({vertexSource, fragmentSource}))
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
