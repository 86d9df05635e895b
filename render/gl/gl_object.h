#pragma once
// One way to own an OpenGL object: a move-only handle that deletes its object when it goes,
// in the context that made it. Programs, shaders, textures, buffers and vertex arrays all use
// it, so no id that claims ownership is ever copied. Framebuffers are QOpenGLFramebufferObject,
// held by one unique_ptr each.
//
// Release handles with their context current (Renderer::cleanup, hooked to the context's
// aboutToBeDestroyed); a handle that dies while another context (or none) is current leaves
// its object to its own context, which frees everything it holds when it goes.

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QPointer>

#include <utility>

namespace lb {

enum class GlKind { Program, Shader, Texture, Buffer, VertexArray };

template <GlKind Kind> class GlObject
{
public:
    GlObject() = default;
    // Takes ownership of `id`, made in the current context.
    explicit GlObject(GLuint id)
        : m_id(id), m_context(id ? QOpenGLContext::currentContext() : nullptr)
    {
    }
    ~GlObject() { reset(); }
    GlObject(const GlObject &) = delete;
    GlObject &operator=(const GlObject &) = delete;
    GlObject(GlObject &&o) noexcept
        : m_id(std::exchange(o.m_id, 0)), m_context(std::exchange(o.m_context, nullptr))
    {
    }
    GlObject &operator=(GlObject &&o) noexcept
    {
        if (this != &o) {
            reset();
            m_id = std::exchange(o.m_id, 0);
            m_context = std::exchange(o.m_context, nullptr);
        }
        return *this;
    }

    // Made with glGen* / glCreate* in the current context.
    static GlObject create()
    {
        QOpenGLExtraFunctions *gl = QOpenGLContext::currentContext()->extraFunctions();
        GLuint id = 0;
        if constexpr (Kind == GlKind::Texture)
            gl->glGenTextures(1, &id);
        else if constexpr (Kind == GlKind::Buffer)
            gl->glGenBuffers(1, &id);
        else if constexpr (Kind == GlKind::VertexArray)
            gl->glGenVertexArrays(1, &id);
        else if constexpr (Kind == GlKind::Program)
            id = gl->glCreateProgram();
        static_assert(Kind != GlKind::Shader, "shaders are made with their stage");
        return GlObject(id);
    }

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }

    void reset()
    {
        QOpenGLContext *current = QOpenGLContext::currentContext();
        if (m_id && current && m_context && QOpenGLContext::areSharing(current, m_context))
            destroy(current->extraFunctions(), m_id);
        m_id = 0;
        m_context = nullptr;
    }

private:
    static void destroy(QOpenGLExtraFunctions *gl, GLuint id)
    {
        if constexpr (Kind == GlKind::Program)
            gl->glDeleteProgram(id);
        else if constexpr (Kind == GlKind::Shader)
            gl->glDeleteShader(id);
        else if constexpr (Kind == GlKind::Texture)
            gl->glDeleteTextures(1, &id);
        else if constexpr (Kind == GlKind::Buffer)
            gl->glDeleteBuffers(1, &id);
        else
            gl->glDeleteVertexArrays(1, &id);
    }

    GLuint m_id = 0;
    QPointer<QOpenGLContext> m_context; // null once that context is gone
};

using GlProgram = GlObject<GlKind::Program>;
using GlShader = GlObject<GlKind::Shader>;
using GlTexture = GlObject<GlKind::Texture>;
using GlBuffer = GlObject<GlKind::Buffer>;
using GlVertexArray = GlObject<GlKind::VertexArray>;

} // namespace lb
