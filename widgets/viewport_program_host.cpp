// The viewport as the program pipeline's host (program_pipeline.h): where a user's program is
// built in the window's context and how its trial frames are drawn there. The pipeline
// decides; these only do.

#include "viewport.h"

#include <QCoreApplication>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>

namespace lb {

// The widget's context made current for one call, unless it already is (initializeGL, a
// trial's frame inside a build): a nested doneCurrent() would leave the caller without it.
class Viewport::Current
{
public:
    explicit Current(Viewport *viewport)
        : m_viewport(viewport),
          m_made(viewport->context() && QOpenGLContext::currentContext() != viewport->context())
    {
        if (m_made)
            m_viewport->makeCurrent();
    }
    ~Current()
    {
        if (m_made)
            m_viewport->doneCurrent();
    }
    Current(const Current &) = delete;
    Current &operator=(const Current &) = delete;

private:
    Viewport *m_viewport;
    bool m_made;
};

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

ProgramBuild Viewport::use(const ProgramSources &sources,
                           const std::function<std::optional<Diagnostic>()> &trial)
{
    const Current current(this);
    return m_renderer.setUserProgram(sources.vertex, sources.fragment, sources.bindings, trial);
}

double Viewport::timeFrame(QSize pixels)
{
    const Current current(this);
    QOpenGLFramebufferObject fbo(pixels, widgetFormat());
    if (!fbo.isValid())
        return 0.0;
    fbo.bind();
    const double ms = m_renderer.renderTimed(m_document->scene(), pixels);
    fbo.release();
    return ms;
}

double Viewport::timeBuiltInFrame(QSize pixels)
{
    return m_renderer.withBuiltIn([&] { return timeFrame(pixels); });
}

void Viewport::useBuiltIn()
{
    const Current current(this);
    m_renderer.clearUserProgram();
}

ProgramBuild Viewport::buildCandidate(const ProgramSources &sources)
{
    const Current current(this);
    return m_renderer.buildCandidate(sources.vertex, sources.fragment, sources.bindings);
}

void Viewport::prepareCandidate()
{
    const Current current(this);
    QOpenGLFramebufferObject fbo(QSize(4, 4), widgetFormat());
    if (!fbo.isValid())
        return;
    fbo.bind();
    m_renderer.prepareCandidate(m_document->scene(), fbo.size());
    fbo.release();
}

void Viewport::adoptCandidate()
{
    const Current current(this); // the program it replaces goes
    m_renderer.adoptCandidate();
}

void Viewport::dropCandidate()
{
    const Current current(this);
    m_renderer.dropCandidate();
}

void Viewport::renewContext()
{
    m_renderer.cleanup(); // the objects died with the context: only the handles go
    // What a reparented widget gets: QOpenGLWidget drops its context and makes a new one,
    // and initializeGL() builds the good program in it (ProgramPipeline::contextReady).
    QEvent windowChange(QEvent::WindowChangeInternal);
    QCoreApplication::sendEvent(this, &windowChange);
}

} // namespace lb
