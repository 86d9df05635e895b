#include "program.h"

#include "dialect.h"

#include <QByteArray>
#include <QElapsedTimer>

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

void addMessage(ProgramBuild &build, ShaderStage stage, const QString &message,
                Diagnostic::Severity severity = Diagnostic::Severity::Error)
{
    Diagnostic d;
    d.stage = stage;
    d.severity = severity;
    d.message = message;
    build.diagnostics.push_back(d);
}

// Returns the shader, or 0; the driver's messages go into `build` on the user's lines.
GLuint compile(QOpenGLExtraFunctions &gl, ShaderStage stage, const QString &source,
               ProgramBuild &build)
{
    if (source.trimmed().isEmpty()) {
        addMessage(build, stage, QString("the %1 shader is empty").arg(stageName(stage)));
        return 0;
    }
    if (source.size() > kMaxSourceCharacters) {
        // Mesa needs many seconds for megabytes of GLSL; a live editor would freeze.
        addMessage(build, stage,
                   QString("the %1 shader is %2 KiB; lightbench compiles sources up to %3 KiB")
                       .arg(stageName(stage))
                       .arg(source.size() / 1024)
                       .arg(kMaxSourceCharacters / 1024));
        return 0;
    }
    const PreparedSource prepared = prepareSource(source);
    const GLuint shader =
        gl.glCreateShader(stage == ShaderStage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
    const QByteArray utf8 = prepared.text.toUtf8();
    const char *text = utf8.constData();
    const GLint length = GLint(utf8.size());
    gl.glShaderSource(shader, 1, &text, &length);
    gl.glCompileShader(shader);
    GLint status = GL_FALSE;
    gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
    for (const Diagnostic &d : parseDriverLog(shaderLog(gl, shader), stage, prepared.linesAdded))
        build.diagnostics.push_back(d);
    if (status != GL_TRUE) {
        // Some drivers fail without a word; the user still needs one.
        if (!build.hasErrors())
            addMessage(build, stage,
                       QString("the %1 shader does not compile (the driver gave no reason)")
                           .arg(stageName(stage)));
        gl.glDeleteShader(shader);
        return 0;
    }
    return shader;
}

std::vector<ActiveUniform> activeUniforms(QOpenGLExtraFunctions &gl, GLuint program)
{
    GLint count = 0, maxLength = 0;
    gl.glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    gl.glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxLength);
    std::vector<ActiveUniform> uniforms;
    QByteArray name(std::max(maxLength, 1), '\0');
    for (GLint i = 0; i < count; ++i) {
        ActiveUniform u;
        GLsizei length = 0;
        gl.glGetActiveUniform(program, GLuint(i), GLsizei(name.size()), &length, &u.size, &u.type,
                              name.data());
        u.name = QString::fromUtf8(name.constData(), length);
        if (u.name.startsWith("gl_"))
            continue;
        u.location = gl.glGetUniformLocation(program, name.constData());
        if (u.name.endsWith("[0]"))
            u.name.chop(3);
        u.semantic = semanticOf(u.name);
        if (const int n = u.components(); n > 0) {
            if (u.isInteger()) {
                GLint v[4] = {};
                gl.glGetUniformiv(program, u.location, v);
                u.initial.assign(v, v + n);
            } else {
                GLfloat v[4] = {};
                gl.glGetUniformfv(program, u.location, v);
                u.initial.assign(v, v + n);
            }
        }
        uniforms.push_back(u);
    }
    return uniforms;
}

} // namespace

int ActiveUniform::components() const
{
    if (size != 1 || location < 0)
        return 0;
    switch (type) {
    case GL_FLOAT:
    case GL_INT:
    case GL_BOOL:
        return 1;
    case GL_FLOAT_VEC2:
    case GL_INT_VEC2:
    case GL_BOOL_VEC2:
        return 2;
    case GL_FLOAT_VEC3:
    case GL_INT_VEC3:
    case GL_BOOL_VEC3:
        return 3;
    case GL_FLOAT_VEC4:
    case GL_INT_VEC4:
    case GL_BOOL_VEC4:
        return 4;
    default:
        return 0;
    }
}

bool ActiveUniform::isInteger() const
{
    switch (type) {
    case GL_INT:
    case GL_INT_VEC2:
    case GL_INT_VEC3:
    case GL_INT_VEC4:
    case GL_BOOL:
    case GL_BOOL_VEC2:
    case GL_BOOL_VEC3:
    case GL_BOOL_VEC4:
        return true;
    default:
        return false;
    }
}

bool ProgramBuild::hasErrors() const
{
    for (const Diagnostic &d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error)
            return true;
    return false;
}

QString ProgramBuild::log() const
{
    QString text;
    for (const Diagnostic &d : diagnostics)
        text +=
            QString("%1:%2:%3: %4: %5\n")
                .arg(stageName(d.stage))
                .arg(d.line)
                .arg(d.column)
                .arg(d.severity == Diagnostic::Severity::Error ? "error" : "warning", d.message);
    return text;
}

const std::vector<AttributeBinding> &attributeBindings()
{
    static const std::vector<AttributeBinding> bindings{
        {"vPosition", kPositionSlot}, {"aVertexPosition", kPositionSlot},
        {"position", kPositionSlot},  {"aPosition", kPositionSlot},
        {"vNormal", kNormalSlot},     {"aVertexNormal", kNormalSlot},
        {"normal", kNormalSlot},      {"aNormal", kNormalSlot},
        {"vColor", kColorSlot},       {"aVertexColor", kColorSlot},
        {"color", kColorSlot},        {"aColor", kColorSlot},
        {"vTexCoord", kTexCoordSlot}, {"aVertexTextureCoord", kTexCoordSlot},
        {"texcoord", kTexCoordSlot},  {"uv", kTexCoordSlot},
        {"aTexCoord", kTexCoordSlot},
    };
    return bindings;
}

double rawBuildMilliseconds(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                            const QString &fragmentSource, bool draw)
{
    const QByteArray sources[2] = {vertexSource.toUtf8(), fragmentSource.toUtf8()};
    QElapsedTimer timer;
    timer.start();
    const GLuint program = gl.glCreateProgram();
    GLuint shaders[2];
    for (int i = 0; i < 2; ++i) {
        shaders[i] = gl.glCreateShader(i ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER);
        const char *text = sources[i].constData();
        gl.glShaderSource(shaders[i], 1, &text, nullptr);
        gl.glCompileShader(shaders[i]);
        gl.glAttachShader(program, shaders[i]);
    }
    gl.glLinkProgram(program);
    GLint status = GL_FALSE;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &status); // waits for a driver that links late
    if (draw) {
        GLuint vao = 0;
        gl.glGenVertexArrays(1, &vao);
        gl.glBindVertexArray(vao);
        gl.glUseProgram(program);
        gl.glDrawArrays(GL_TRIANGLES, 0, 3);
        gl.glFinish();
        gl.glUseProgram(0);
        gl.glBindVertexArray(0);
        gl.glDeleteVertexArrays(1, &vao);
    }
    const double ms = double(timer.nsecsElapsed()) * 1e-6;
    for (GLuint shader : shaders)
        gl.glDeleteShader(shader);
    gl.glDeleteProgram(program);
    return ms;
}

ProgramBuild buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource)
{
    ProgramBuild result;
    const GLuint vs = compile(gl, ShaderStage::Vertex, vertexSource, result);
    const GLuint fs = compile(gl, ShaderStage::Fragment, fragmentSource, result);
    if (!vs || !fs) {
        gl.glDeleteShader(vs);
        gl.glDeleteShader(fs);
        return result;
    }
    const GLuint program = gl.glCreateProgram();
    gl.glAttachShader(program, vs);
    gl.glAttachShader(program, fs);
    for (const AttributeBinding &b : attributeBindings())
        gl.glBindAttribLocation(program, b.slot, b.name);
    gl.glLinkProgram(program);
    gl.glDetachShader(program, vs);
    gl.glDetachShader(program, fs);
    gl.glDeleteShader(vs);
    gl.glDeleteShader(fs);

    GLint status = GL_FALSE;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &status);
    for (const Diagnostic &d : parseDriverLog(programLog(gl, program), ShaderStage::Link))
        result.diagnostics.push_back(d);
    if (status != GL_TRUE) {
        if (!result.hasErrors())
            addMessage(result, ShaderStage::Link, "the program does not link (no reason given)");
        gl.glDeleteProgram(program);
        return result;
    }
    // Two programs link but cannot draw the object; they are refused like a failed link, so
    // that the last good program keeps drawing.
    bool readsPosition = false;
    for (const AttributeBinding &b : attributeBindings())
        readsPosition = readsPosition ||
                        (b.slot == kPositionSlot && gl.glGetAttribLocation(program, b.name) >= 0);
    if (!readsPosition)
        addMessage(result, ShaderStage::Vertex,
                   "no position input: the mesh reaches the shader through an attribute named "
                   "vPosition, aVertexPosition, position or aPosition");
    if (!writesFragmentColour(fragmentSource))
        addMessage(result, ShaderStage::Fragment,
                   "the fragment shader writes no colour: assign gl_FragColor (no #version, "
                   "#version 100) or declare an out vec4 (#version 300 es, 330 and later)");
    if (result.hasErrors()) {
        gl.glDeleteProgram(program);
        return result;
    }
    result.program = program;
    result.uniforms = activeUniforms(gl, program);
    return result;
}

} // namespace lb
