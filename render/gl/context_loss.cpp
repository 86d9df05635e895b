#include "context_loss.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace lb {

namespace {
QOpenGLContext *g_resetForTesting = nullptr;
} // namespace

void reportResetForTesting(QOpenGLContext *context)
{
    g_resetForTesting = context;
}

bool contextWasReset(QOpenGLContext &context)
{
    if (g_resetForTesting == &context) {
        g_resetForTesting = nullptr;
        return true;
    }
    if (!context.isValid())
        return true;
    if (!context.format().testOption(QSurfaceFormat::ResetNotification))
        return false;
    using ResetStatus = GLenum (*)();
    auto status = reinterpret_cast<ResetStatus>(context.getProcAddress("glGetGraphicsResetStatus"));
    if (!status)
        status =
            reinterpret_cast<ResetStatus>(context.getProcAddress("glGetGraphicsResetStatusARB"));
    return status && status() != GL_NO_ERROR;
}

} // namespace lb
