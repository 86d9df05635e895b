#include "program.h"

#include "dialect.h"
#include "legacy_builtins.h"
#include "loops.h"
#include "macro_expansion.h"
#include "presets.h"
#include "unfed_inputs.h"
#include "webgl1_translation.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QRegularExpression>

#include <algorithm>
#include <utility>

namespace lb {

namespace {

// The translation context of this file's messages. A sentence naming a stage is written out
// for each stage: the word's case and gender change the sentence around it.
struct ProgramMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Program)
};

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

// What the driver is handed: the source as written (WebGL 1 under "#version 100"), WebGL 1
// translated to GLSL 3.30, or a fixed-function era program translated (legacyProgram()).
enum class Translation { None, WebGl1, Legacy };

// Returns the shader, or none; the driver's messages go into `build` on the user's lines.
GlShader compile(QOpenGLExtraFunctions &gl, ShaderStage stage, const QString &source,
                 Translation translation, ProgramBuild &build)
{
    const bool vertex = stage == ShaderStage::Vertex; // compiled: vertex or fragment
    if (source.trimmed().isEmpty()) {
        addMessage(build, stage,
                   vertex ? ProgramMessages::tr("the vertex shader is empty")
                          : ProgramMessages::tr("the fragment shader is empty"));
        return {};
    }
    if (source.size() > kMaxSourceCharacters) {
        // Mesa needs many seconds for megabytes of GLSL; a live editor would freeze.
        addMessage(
            build, stage,
            (vertex
                 ? ProgramMessages::tr("the vertex shader is %1 KiB; lightbench compiles sources "
                                       "up to %2 KiB")
                 : ProgramMessages::tr("the fragment shader is %1 KiB; lightbench compiles "
                                       "sources up to %2 KiB"))
                .arg(source.size() / 1024)
                .arg(kMaxSourceCharacters / 1024));
        return {};
    }
    if (std::optional<Diagnostic> refusal = readLoops(source, stage).expansionRefusal) {
        // Mesa's preprocessor expands macros without a bound (issue 29: 946 bytes, 24 GB):
        // every route to the driver (the window, --check, --render, --grade) comes here.
        build.diagnostics.push_back(*refusal);
        return {};
    }
    const PreparedSource prepared =
        translation == Translation::Legacy
            ? prepareLegacySource(source, stage)
            : prepareSource(source, stage, translation == Translation::WebGl1);
    GlShader shader(
        gl.glCreateShader(stage == ShaderStage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER));
    const QByteArray utf8 = prepared.text.toUtf8();
    const char *text = utf8.constData();
    const GLint length = GLint(utf8.size());
    gl.glShaderSource(shader.id(), 1, &text, &length);
    gl.glCompileShader(shader.id());
    GLint status = GL_FALSE;
    gl.glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &status);
    for (Diagnostic d : parseDriverLog(shaderLog(gl, shader.id()), stage, prepared.linesAdded)) {
        if (translation == Translation::Legacy)
            d.message = withLegacyNames(d.message);
        build.diagnostics.push_back(d);
    }
    if (status != GL_TRUE) {
        // Some drivers fail without a word; the user still needs one.
        if (!build.hasErrors())
            addMessage(
                build, stage,
                vertex
                    ? ProgramMessages::tr("the vertex shader does not compile (the driver gave no "
                                          "reason)")
                    : ProgramMessages::tr("the fragment shader does not compile (the driver gave "
                                          "no reason)"));
        return {};
    }
    // Before the driver's silent optimisation draws garbage (or a GPU resets): endless
    // loops named on their line.
    for (const Diagnostic &d : endlessLoopWarnings(source, stage))
        build.diagnostics.push_back(d);
    return shader;
}

} // namespace

bool acceptsVersion100(QOpenGLExtraFunctions &gl)
{
    GlShader shader(gl.glCreateShader(GL_FRAGMENT_SHADER));
    const char *text = "#version 100\nprecision mediump float;\n"
                       "void main() { gl_FragColor = vec4(1.0); }\n";
    gl.glShaderSource(shader.id(), 1, &text, nullptr);
    gl.glCompileShader(shader.id());
    GLint status = GL_FALSE;
    gl.glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &status);
    return status == GL_TRUE;
}

namespace {

// The GLSL type of a reflected uniform, without GL enums beyond this file.
void describeType(GLenum type, ActiveUniform &u)
{
    struct Entry
    {
        GLenum type;
        UniformKind kind;
        int width;
    };
    static const Entry table[] = {
        {GL_FLOAT, UniformKind::Float, 1},       {GL_FLOAT_VEC2, UniformKind::Float, 2},
        {GL_FLOAT_VEC3, UniformKind::Float, 3},  {GL_FLOAT_VEC4, UniformKind::Float, 4},
        {GL_INT, UniformKind::Int, 1},           {GL_INT_VEC2, UniformKind::Int, 2},
        {GL_INT_VEC3, UniformKind::Int, 3},      {GL_INT_VEC4, UniformKind::Int, 4},
        {GL_BOOL, UniformKind::Bool, 1},         {GL_BOOL_VEC2, UniformKind::Bool, 2},
        {GL_BOOL_VEC3, UniformKind::Bool, 3},    {GL_BOOL_VEC4, UniformKind::Bool, 4},
        {GL_FLOAT_MAT2, UniformKind::Matrix, 2}, {GL_FLOAT_MAT3, UniformKind::Matrix, 3},
        {GL_FLOAT_MAT4, UniformKind::Matrix, 4}, {GL_SAMPLER_2D, UniformKind::Sampler, 1},
    };
    u.kind = UniformKind::Other;
    u.width = 1;
    for (const Entry &e : table)
        if (e.type == type) {
            u.kind = e.kind;
            u.width = e.width;
        }
}

struct ActiveAttribute
{
    QString name;
    GLint location = -1;
};

std::vector<ActiveAttribute> activeAttributes(QOpenGLExtraFunctions &gl, GLuint program)
{
    GLint count = 0, maxLength = 0;
    gl.glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    gl.glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &maxLength);
    std::vector<ActiveAttribute> attributes;
    QByteArray name(std::max(maxLength, 1), '\0');
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 1;
        GLenum type = 0;
        gl.glGetActiveAttrib(program, GLuint(i), GLsizei(name.size()), &length, &size, &type,
                             name.data());
        if (length <= 0 || name.startsWith("gl_"))
            continue;
        attributes.push_back({QString::fromUtf8(name.constData(), length),
                              gl.glGetAttribLocation(program, name.constData())});
    }
    return attributes;
}

// The slot of an attribute name in the table (attributeBindings()); none for another name.
std::optional<AttributeSlot> tableSlot(const QString &name)
{
    const auto &table = attributeBindings();
    const auto known = std::find_if(table.begin(), table.end(), [&](const AttributeBinding &b) {
        return name == QLatin1String(b.name);
    });
    return known != table.end() ? std::optional<AttributeSlot>(known->slot) : std::nullopt;
}

// Binds each active attribute of a name in no table to the slot its name says, where that
// slot is free and it is not there yet; whether any was (the program must link again).
bool bindByNameParts(QOpenGLExtraFunctions &gl, GLuint program)
{
    const std::vector<ActiveAttribute> attributes = activeAttributes(gl, program);
    const auto known = [](const QString &name) { return tableSlot(name).has_value(); };
    std::vector<GLint> taken; // by a known name, or by one bound here
    for (const ActiveAttribute &a : attributes)
        if (known(a.name))
            taken.push_back(a.location);
    bool bound = false;
    for (const ActiveAttribute &a : attributes) {
        if (known(a.name))
            continue;
        const std::optional<AttributeSlot> slot = slotByNameParts(a.name);
        if (!slot || a.location == GLint(*slot) ||
            std::find(taken.begin(), taken.end(), GLint(*slot)) != taken.end())
            continue;
        gl.glBindAttribLocation(program, *slot, a.name.toUtf8().constData());
        taken.push_back(GLint(*slot));
        bound = true;
    }
    return bound;
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
        GLint size = 1;
        GLenum type = 0;
        gl.glGetActiveUniform(program, GLuint(i), GLsizei(name.size()), &length, &size, &type,
                              name.data());
        u.size = size;
        describeType(type, u);
        u.name = QString::fromUtf8(name.constData(), length);
        if (u.name.startsWith("gl_"))
            continue;
        u.location = gl.glGetUniformLocation(program, name.constData());
        if (u.name.endsWith("[0]"))
            u.name.chop(3);
        u.semantic = semanticOf(u.name, shapeOf(u.kind));
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

const std::vector<AttributeBinding> &attributeBindings()
{
    // The course's (vPosition, aVertexPosition...), LearnOpenGL's (aPos, aNormal,
    // aTexCoords), webglfundamentals' and glslViewer's (a_position, a_normal, a_texcoord),
    // MDN's (aVertexPosition, aTextureCoord), Angel's and three.js's (vPosition, position,
    // uv), the GLSL Cookbook's (VertexPosition, VertexNormal, VertexTexCoord).
    static const std::vector<AttributeBinding> bindings{
        {"vPosition", kPositionSlot},
        {"aVertexPosition", kPositionSlot},
        {"position", kPositionSlot},
        {"aPosition", kPositionSlot},
        {"aPos", kPositionSlot},
        {"a_position", kPositionSlot},
        {"VertexPosition", kPositionSlot},
        {"a_Position", kPositionSlot},
        {"vNormal", kNormalSlot},
        {"aVertexNormal", kNormalSlot},
        {"normal", kNormalSlot},
        {"aNormal", kNormalSlot},
        {"a_normal", kNormalSlot},
        {"VertexNormal", kNormalSlot},
        {"a_Normal", kNormalSlot},
        {"vColor", kColorSlot},
        {"aVertexColor", kColorSlot},
        {"color", kColorSlot},
        {"aColor", kColorSlot},
        {"a_color", kColorSlot},
        {"VertexColor", kColorSlot},
        {"a_Color", kColorSlot},
        {"vTexCoord", kTexCoordSlot},
        {"aVertexTextureCoord", kTexCoordSlot},
        {"texcoord", kTexCoordSlot},
        {"uv", kTexCoordSlot},
        {"aTexCoord", kTexCoordSlot},
        {"aTexCoords", kTexCoordSlot},
        {"aTextureCoord", kTexCoordSlot},
        {"a_texcoord", kTexCoordSlot},
        {"a_texCoord", kTexCoordSlot},
        {"VertexTexCoord", kTexCoordSlot},
        {"a_TexCoord", kTexCoordSlot},
    };
    return bindings;
}

std::optional<AttributeSlot> slotByNameParts(const QString &name)
{
    // "Vertex" says which stage, not what: inVertexNormal is a normal, inVertexTexCoord
    // texture coordinates (and "vertex" holds "tex"); alone (aVertex) it is the position.
    QString n = name.toLower();
    const bool vertex = n.contains("vert");
    n.remove("vertex");
    if (n.contains("norm"))
        return kNormalSlot;
    if (n.contains("tex") || n.contains("uv"))
        return kTexCoordSlot;
    if (n.contains("col"))
        return kColorSlot;
    if (n.contains("pos") || vertex)
        return kPositionSlot;
    return std::nullopt;
}

double rawBuildMilliseconds(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                            const QString &fragmentSource, bool draw)
{
    const QByteArray sources[2] = {vertexSource.toUtf8(), fragmentSource.toUtf8()};
    QElapsedTimer timer;
    timer.start();
    const GlProgram program = GlProgram::create();
    GlShader shaders[2];
    for (int i = 0; i < 2; ++i) {
        shaders[i] = GlShader(gl.glCreateShader(i ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER));
        const char *text = sources[i].constData();
        gl.glShaderSource(shaders[i].id(), 1, &text, nullptr);
        gl.glCompileShader(shaders[i].id());
        gl.glAttachShader(program.id(), shaders[i].id());
    }
    gl.glLinkProgram(program.id());
    GLint status = GL_FALSE;
    gl.glGetProgramiv(program.id(), GL_LINK_STATUS, &status); // waits for a late linker
    if (draw) {
        const GlVertexArray vao = GlVertexArray::create();
        gl.glBindVertexArray(vao.id());
        gl.glUseProgram(program.id());
        gl.glDrawArrays(GL_TRIANGLES, 0, 3);
        gl.glFinish();
        gl.glUseProgram(0);
        gl.glBindVertexArray(0);
    }
    return double(timer.nsecsElapsed()) * 1e-6; // the objects go after the clock stops
}

namespace {

// buildProgram(), with the sources translated to GLSL 3.30 or not.
BuiltProgram buildTranslatedOrNot(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                                  const QString &fragmentSource, Translation translate,
                                  const UniformBindings &bindings)
{
    BuiltProgram result;
    ProgramBuild &build = result.build;
    const GlShader vs = compile(gl, ShaderStage::Vertex, vertexSource, translate, build);
    const GlShader fs = compile(gl, ShaderStage::Fragment, fragmentSource, translate, build);
    if (!vs || !fs)
        return result;
    GlProgram program = GlProgram::create();
    gl.glAttachShader(program.id(), vs.id());
    gl.glAttachShader(program.id(), fs.id());
    for (const AttributeBinding &b : attributeBindings())
        gl.glBindAttribLocation(program.id(), b.slot, b.name);
    gl.glLinkProgram(program.id());
    GLint status = GL_FALSE;
    gl.glGetProgramiv(program.id(), GL_LINK_STATUS, &status);
    // Names in no table are bound by what they say (inPos, vertex_normal) and the program
    // linked once more; a layout(location = N) the shader gives keeps its N either way.
    if (status == GL_TRUE && bindByNameParts(gl, program.id())) {
        gl.glLinkProgram(program.id());
        gl.glGetProgramiv(program.id(), GL_LINK_STATUS, &status);
    }
    gl.glDetachShader(program.id(), vs.id());
    gl.glDetachShader(program.id(), fs.id());

    for (const Diagnostic &d : parseDriverLog(programLog(gl, program.id()), ShaderStage::Link))
        build.diagnostics.push_back(d);
    if (status != GL_TRUE) {
        if (!build.hasErrors())
            addMessage(build, ShaderStage::Link,
                       ProgramMessages::tr("the program does not link (no reason given)"));
        return result;
    }
    // Two programs link but cannot draw the object; they are refused like a failed link, so
    // that the last good program keeps drawing.
    const std::vector<ActiveAttribute> attributes = activeAttributes(gl, program.id());
    const bool readsPosition =
        std::any_of(attributes.begin(), attributes.end(),
                    [](const ActiveAttribute &a) { return a.location == GLint(kPositionSlot); });
    if (!readsPosition)
        addMessage(build, ShaderStage::Vertex,
                   ProgramMessages::tr(
                       "no position input: the mesh reaches the shader through the attribute "
                       "at layout(location = 0), or one named aPos, a_position, vPosition, "
                       "aVertexPosition or position, or with pos or vert in its name"));
    if (!writesFragmentColour(fragmentSource))
        addMessage(
            build, ShaderStage::Fragment,
            ProgramMessages::tr("the fragment shader writes no colour: assign gl_FragColor (no "
                                "#version, #version 100) or declare an out vec4 (#version 300 es, "
                                "330 and later)"));
    if (build.hasErrors())
        return result;
    build.linked = true;
    std::vector<PlacedInput> placed;
    for (const ActiveAttribute &a : attributes) {
        build.attributes.push_back({a.name, int(a.location)});
        std::optional<AttributeSlot> slot = tableSlot(a.name);
        if (!slot)
            slot = slotByNameParts(a.name);
        placed.push_back({a.name, int(a.location), slot ? int(*slot) : -1});
    }
    for (const Diagnostic &d : misplacedInputWarnings(placed, vertexSource))
        build.diagnostics.push_back(d);
    build.uniforms = activeUniforms(gl, program.id());
    for (const Diagnostic &d : applyBindings(build.uniforms, bindings))
        build.diagnostics.push_back(d);
    for (const Diagnostic &d : unfedInputWarnings(build.uniforms, vertexSource, fragmentSource))
        build.diagnostics.push_back(d);
    result.program = std::move(program);
    return result;
}

// The errors a driver gives a global initialised from something that is not a constant
// (Mesa: "initializer of global variable `x' must be a constant expression"), which GLSL ES
// 1.00 forbids and browsers accept: ANGLE moves the initialisation into main with a warning.
std::vector<const Diagnostic *> globalInitialiserErrors(const ProgramBuild &build)
{
    static const QRegularExpression initialiser("initiali[sz]",
                                                QRegularExpression::CaseInsensitiveOption);
    std::vector<const Diagnostic *> found;
    for (const Diagnostic &d : build.diagnostics)
        if (d.severity == Diagnostic::Severity::Error && d.message.contains(initialiser))
            found.push_back(&d);
    return found;
}

} // namespace

BuiltProgram buildProgram(QOpenGLExtraFunctions &gl, const QString &vertexSource,
                          const QString &fragmentSource, const UniformBindings &bindings)
{
    // GLSL 1.20's built-ins are fed as the names of the semantic table (legacy_builtins.h),
    // whatever the driver's profile: Mesa's core context compiles them and leaves them unfed.
    if (legacyProgram(vertexSource, fragmentSource))
        return buildTranslatedOrNot(gl, vertexSource, fragmentSource, Translation::Legacy,
                                    bindings);
    const bool translate = translatesWebGl1();
    BuiltProgram built =
        buildTranslatedOrNot(gl, vertexSource, fragmentSource,
                             translate ? Translation::WebGl1 : Translation::None, bindings);
    const std::vector<const Diagnostic *> initialisers = globalInitialiserErrors(built.build);
    if (built.build.ok() || translate || initialisers.empty() ||
        prepareSource(vertexSource).version != "100" ||
        prepareSource(fragmentSource).version != "100")
        return built;
    // WebGL 1 as browsers run it: GLSL 3.30 takes any global initialiser, so the program runs
    // translated (both stages: an ES 1.00 stage does not link with a 3.30 one), and each line
    // the driver refused gets a warning instead.
    BuiltProgram translated =
        buildTranslatedOrNot(gl, vertexSource, fragmentSource, Translation::WebGl1, bindings);
    if (!translated.build.ok())
        return built;
    for (const Diagnostic *refused : initialisers) {
        Diagnostic d = *refused;
        d.severity = Diagnostic::Severity::Warning;
        d.message =
            ProgramMessages::tr(
                "a global variable initialised from a uniform or another variable: GLSL ES 1.00 "
                "asks for a constant, browsers run it (WebGL warns); lightbench runs this program "
                "translated to GLSL 3.30 (the driver said: %1)")
                .arg(refused->message);
        translated.build.diagnostics.insert(translated.build.diagnostics.begin(), d);
    }
    return translated;
}

BuiltProgram buildBuiltIn(QOpenGLExtraFunctions &gl, const QString &name, QString &error,
                          const QString &fragment)
{
    const Preset pair{name, ":/shaders/" + name};
    const Preset fragmentPair{name, ":/shaders/" + (fragment.isEmpty() ? name : fragment)};
    BuiltProgram built = buildProgram(gl, pair.vertexSource(), fragmentPair.fragmentSource());
    if (!built.build.ok())
        //: %1 a built-in program's name, %2 its build log
        error +=
            ProgramMessages::tr("built-in shader '%1' failed:\n%2").arg(name, built.build.log());
    return built;
}

QString withDefine(const QString &source, const QString &name, int value)
{
    const QRegularExpression line("^#define " + QRegularExpression::escape(name) + " \\d+$",
                                  QRegularExpression::MultilineOption);
    QString out = source;
    if (!line.match(out).hasMatch())
        return {};
    out.replace(line, QString("#define %1 %2").arg(name).arg(value));
    return out;
}

std::optional<bool> shippedBuiltIn(const QString &vertexSource, const QString &fragmentSource)
{
    for (bool gouraud : {true, false}) {
        const Preset &p = builtInPreset(gouraud);
        if (vertexSource == p.vertexSource() && fragmentSource == p.fragmentSource())
            return gouraud;
    }
    return std::nullopt;
}

int builtInLightCount(const Scene &scene)
{
    int count = 1;
    for (int i = 0; i < kMaxLights; ++i)
        if (scene.lights[std::size_t(i)].enabled)
            count = i + 1;
    return count;
}

bool builtInNeedsLightFactors(const Scene &scene)
{
    const Light &first = scene.lights[0]; // Show attenuation shows light 1's, on or off
    if (scene.shading.show == ShowChoice::Attenuation && first.position.w != 0.0f &&
        first.attenuation != glm::vec3(1.0f, 0.0f, 0.0f))
        return true;
    const int count = builtInLightCount(scene);
    for (int i = 0; i < count; ++i) {
        const Light &l = scene.lights[std::size_t(i)];
        const bool attenuated =
            l.position.w != 0.0f && l.attenuation != glm::vec3(1.0f, 0.0f, 0.0f);
        if (l.enabled && (attenuated || l.spot.cutoffDegrees < limits::kMaxSpotCutoff))
            return true;
    }
    return false;
}

BuiltInVariant builtInVariant(const Scene &scene, bool gouraud)
{
    return {gouraud, builtInLightCount(scene), builtInNeedsLightFactors(scene),
            scene.shading.show != ShowChoice::Colour,
            gouraud && scene.shading.shading == Shading::Flat};
}

BuiltProgram buildSpecialisedBuiltIn(QOpenGLExtraFunctions &gl, const BuiltInVariant &variant,
                                     QString &error)
{
    const Preset &preset = builtInPreset(variant.gouraud);
    // Each "#define NAME N" line a stage has is set; the stage with the light loop must have
    // MAX_LIGHTS, LIGHT_FACTORS and SHOW_CHOICES.
    const std::pair<const char *, int> defines[] = {{"MAX_LIGHTS", variant.lights},
                                                    {"LIGHT_FACTORS", variant.lightFactors ? 1 : 0},
                                                    {"SHOW_CHOICES", variant.showChoices ? 1 : 0},
                                                    {"FLAT_SHADING", variant.flat ? 1 : 0}};
    const auto specialise = [&](QString source, int &set) {
        for (const auto &[name, value] : defines)
            if (const QString changed = withDefine(source, name, value); !changed.isEmpty()) {
                source = changed;
                ++set;
            }
        return source;
    };
    int vertexSet = 0, fragmentSet = 0;
    const QString v = specialise(preset.vertexSource(), vertexSet);
    const QString f = specialise(preset.fragmentSource(), fragmentSet);
    if (std::max(vertexSet, fragmentSet) < 3) {
        error += ProgramMessages::tr(
                     "built-in shader '%1' lacks a '#define MAX_LIGHTS', 'LIGHT_FACTORS' or "
                     "'SHOW_CHOICES' line\n")
                     .arg(preset.name);
        return {};
    }
    BuiltProgram built = buildProgram(gl, v, f);
    if (!built.build.ok())
        error += ProgramMessages::tr("built-in shader '%1' failed:\n%2")
                     .arg(preset.name, built.build.log());
    return built;
}

} // namespace lb
