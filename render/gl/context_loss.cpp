#include "context_loss.h"

namespace lb {

namespace {
QOpenGLContext *g_resetForTesting = nullptr;
} // namespace

void reportResetForTesting(QOpenGLContext *context)
{
    g_resetForTesting = context;
}

void ResetStatus::attach(QOpenGLContext *context)
{
    m_context = context;
    m_query = nullptr;
    if (!context || !context->format().testOption(QSurfaceFormat::ResetNotification))
        return;
    m_query = reinterpret_cast<Query>(context->getProcAddress("glGetGraphicsResetStatus"));
    if (!m_query)
        m_query = reinterpret_cast<Query>(context->getProcAddress("glGetGraphicsResetStatusARB"));
}

bool ResetStatus::wasReset() const
{
    if (!m_context)
        return false;
    if (g_resetForTesting == m_context) {
        g_resetForTesting = nullptr;
        return true;
    }
    return !m_context->isValid() || (m_query && m_query() != GL_NO_ERROR);
}

} // namespace lb
