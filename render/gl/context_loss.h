#pragma once
// A context the driver reset (GPU recovery after a shader ran too long: Windows TDR, Linux
// GPU reset) loses every object in it. With QSurfaceFormat::ResetNotification (set by
// setDefaultGlFormat) the driver says so: glGetGraphicsResetStatus reports it, and Qt marks
// the context invalid at its next makeCurrent.

#include <QOpenGLContext>
#include <QPointer>

namespace lb {

// Asks the driver, once a frame, whether a context was reset. The query is resolved once,
// when the context is attached, not per frame.
class ResetStatus
{
public:
    // With `context` current (a new one replaces the one before).
    void attach(QOpenGLContext *context);
    // With the attached context current: whether it was reset, or is no longer valid. False
    // where the driver cannot tell (no robustness).
    bool wasReset() const;

private:
    using Query = GLenum (*)();
    QPointer<QOpenGLContext> m_context;
    Query m_query = nullptr;
};

// Makes the next wasReset() of `context` say it was reset, as the driver would after a GPU
// reset, which no test can cause on Mesa; the recovery that follows is the real one.
void reportResetForTesting(QOpenGLContext *context);

} // namespace lb
