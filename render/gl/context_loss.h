#pragma once
// A context the driver reset (GPU recovery after a shader ran too long: Windows TDR, Linux
// GPU reset) loses every object in it. With QSurfaceFormat::ResetNotification (set by
// setDefaultGlFormat) the driver says so: glGetGraphicsResetStatus reports it, and Qt marks
// the context invalid at its next makeCurrent.

class QOpenGLContext;

namespace lb {

// With `context` current: whether it was reset, or is no longer valid. False where the driver
// cannot tell (no robustness).
bool contextWasReset(QOpenGLContext &context);

// Makes the next contextWasReset(context) say it was reset, as the driver would after a GPU
// reset, which no test can cause on Mesa; the recovery that follows is the real one.
void reportResetForTesting(QOpenGLContext *context);

} // namespace lb
