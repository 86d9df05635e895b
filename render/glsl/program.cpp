#include "program.h"

#include <QByteArray>

namespace lb {

namespace {

// Reads an info log of `length` bytes (terminator included) through `read`.
template <typename Read> QString infoLog(GLint length, Read read)
{
    QByteArray log(std::max(length, 1), '\0');
    read(GLsizei(log.size()), log.data());
    return QString::fromUtf8(log.constData()).trimmed();
}

QString shaderLog(QOpenGLExtraFunctions &gl, GLuint shader)
{
    GLint length = 0;
    gl.glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    return infoLog(length,
                   [&](GLsizei n, char *buf) { gl.glGetShaderInfoLog(shader, n, nullptr, buf); });
}

QString programLog(QOpenGLExtraFunctions &gl, GLuint program)
{
    GLint length = 0;
    gl.glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    return infoLog(length,
                   [&](GLsizei n, char *buf) { gl.glGetProgramInfoLog(program, n, nullptr, buf); });
}

// Returns the shader, or 0 with the log appended to `log`.
GLuint compile(QOpenGLExtraFunctions &gl, GLenum stage, const QString &source, QString &log)
{
    const GLuint shader = gl.glCreateShader(stage);
    const QByteArray utf8 = source.toUtf8();
    const char *text = utf8.constData();
    const GLint length = GLint(utf8.size());
    gl.glShaderSource(shader, 1, &text, &length);
    gl.glCompileShader(shader);
    GLint status = GL_FALSE;
    gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
    const QString stageLog = shaderLog(gl, shader);
    if (!stageLog.isEmpty())
        log += (stage == GL_VERTEX_SHADER ? "vertex: " : "fragment: ") + stageLog + '\n';
    if (status != GL_TRUE) {
        gl.glDeleteShader(shader);
        return 0;
    }
    return shader;
}

} // namespace

const std::vector<std::pair<const char *, AttributeSlot>> &attributeBindings()
{
    static const std::vector<std::pair<const char *, AttributeSlot>> bindings{
        {"vPosition", kPositionSlot},
        {"vNormal", kNormalSlot},
        {"vColor", kColorSlot},
        {"vTexCoord", kTexCoordSlot},
    };
    return bindings;
}

ProgramBuild buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource)
{
    ProgramBuild result;
    const GLuint vs = compile(gl, GL_VERTEX_SHADER, vertexSource, result.log);
    const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragmentSource, result.log);
    if (!vs || !fs) {
        gl.glDeleteShader(vs);
        gl.glDeleteShader(fs);
        return result;
    }
    const GLuint program = gl.glCreateProgram();
    gl.glAttachShader(program, vs);
    gl.glAttachShader(program, fs);
    for (const auto &[name, slot] : attributeBindings())
        gl.glBindAttribLocation(program, slot, name);
    gl.glLinkProgram(program);
    gl.glDetachShader(program, vs);
    gl.glDetachShader(program, fs);
    gl.glDeleteShader(vs);
    gl.glDeleteShader(fs);

    GLint status = GL_FALSE;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &status);
    const QString linkLog = programLog(gl, program);
    if (!linkLog.isEmpty())
        result.log += "link: " + linkLog + '\n';
    if (status != GL_TRUE) {
        gl.glDeleteProgram(program);
        return result;
    }
    result.program = program;
    return result;
}

} // namespace lb
