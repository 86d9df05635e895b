#include "legacy_builtins.h"

#include "dialect.h"

#include <QRegularExpression>

namespace lb {

namespace {

// A built-in word and what it is in each stage (an empty name: not a word of that stage,
// left for the driver to refuse).
struct Word
{
    const char *name;
    const char *vertex; // replacement, declaration
    const char *vertexDeclaration;
    const char *fragment;
    const char *fragmentDeclaration;
};

// The attributes at the mesh's slots (program.h: 0 positions, 1 normals, 2 texture
// coordinates, 3 colours); the interpolated colour and texture coordinates as outputs and
// inputs; the matrices as the uniforms the semantic table names. The texture matrices are the
// identity (the workbench has none).
const Word kWords[] = {
    {"gl_Vertex", "lb_Vertex", "layout(location = 0) in vec4 lb_Vertex;", "", ""},
    {"gl_Normal", "lb_Normal", "layout(location = 1) in vec3 lb_Normal;", "", ""},
    {"gl_MultiTexCoord0", "lb_MultiTexCoord0", "layout(location = 2) in vec4 lb_MultiTexCoord0;",
     "", ""},
    {"gl_Color", "lb_Color", "layout(location = 3) in vec4 lb_Color;", "lb_FrontColor",
     "in vec4 lb_FrontColor;"},
    {"gl_FrontColor", "lb_FrontColor", "out vec4 lb_FrontColor;", "", ""},
    {"gl_TexCoord", "lb_TexCoord", "out vec4 lb_TexCoord[4];", "lb_TexCoord",
     "in vec4 lb_TexCoord[4];"},
    {"gl_ModelViewMatrix", "lb_ModelViewMatrix", "uniform mat4 lb_ModelViewMatrix;",
     "lb_ModelViewMatrix", "uniform mat4 lb_ModelViewMatrix;"},
    {"gl_ProjectionMatrix", "lb_ProjectionMatrix", "uniform mat4 lb_ProjectionMatrix;",
     "lb_ProjectionMatrix", "uniform mat4 lb_ProjectionMatrix;"},
    {"gl_ModelViewProjectionMatrix", "lb_ModelViewProjectionMatrix",
     "uniform mat4 lb_ModelViewProjectionMatrix;", "lb_ModelViewProjectionMatrix",
     "uniform mat4 lb_ModelViewProjectionMatrix;"},
    {"gl_NormalMatrix", "lb_NormalMatrix", "uniform mat3 lb_NormalMatrix;", "lb_NormalMatrix",
     "uniform mat3 lb_NormalMatrix;"},
    {"gl_TextureMatrix", "lb_TextureMatrix",
     "const mat4 lb_TextureMatrix[4] = mat4[4](mat4(1.0), mat4(1.0), mat4(1.0), mat4(1.0));",
     "lb_TextureMatrix",
     "const mat4 lb_TextureMatrix[4] = mat4[4](mat4(1.0), mat4(1.0), mat4(1.0), mat4(1.0));"},
    {"gl_MaxLights", "lb_MaxLights", "const int lb_MaxLights = 4;", "lb_MaxLights",
     "const int lb_MaxLights = 4;"},
};

struct Member
{
    const char *block; // as the replacement spells it: lb_<block>_<member>
    const char *member;
    const char *type;
    const char *constant; // the value where the model has none (a const, no uniform)
};

// gl_LightSource's and the products' members hold one light each; the material's one value.
// The model has no emission and no ambient light apart from the lights' Ia: those are 0.
const Member kMembers[] = {
    {"LightSource", "ambient", "vec4", nullptr},
    {"LightSource", "diffuse", "vec4", nullptr},
    {"LightSource", "specular", "vec4", nullptr},
    {"LightSource", "position", "vec4", nullptr},
    {"LightSource", "halfVector", "vec4", nullptr},
    {"LightSource", "spotDirection", "vec3", nullptr},
    {"LightSource", "spotExponent", "float", nullptr},
    {"LightSource", "spotCutoff", "float", nullptr},
    {"LightSource", "spotCosCutoff", "float", nullptr},
    {"LightSource", "constantAttenuation", "float", nullptr},
    {"LightSource", "linearAttenuation", "float", nullptr},
    {"LightSource", "quadraticAttenuation", "float", nullptr},
    {"FrontLightProduct", "ambient", "vec4", nullptr},
    {"FrontLightProduct", "diffuse", "vec4", nullptr},
    {"FrontLightProduct", "specular", "vec4", nullptr},
    {"FrontMaterial", "ambient", "vec4", nullptr},
    {"FrontMaterial", "diffuse", "vec4", nullptr},
    {"FrontMaterial", "specular", "vec4", nullptr},
    {"FrontMaterial", "shininess", "float", nullptr},
    {"FrontMaterial", "emission", "vec4", "vec4(0.0, 0.0, 0.0, 1.0)"},
    {"LightModel", "ambient", "vec4", "vec4(0.0, 0.0, 0.0, 1.0)"},
    {"FrontLightModelProduct", "sceneColor", "vec4", "vec4(0.0, 0.0, 0.0, 1.0)"},
};

// The blocks by their GLSL names; the back face's are the front's (one material here).
struct Block
{
    const char *name;
    const char *as;
    bool indexed;
};
const Block kBlocks[] = {
    {"gl_LightSource", "LightSource", true},
    {"gl_FrontLightProduct", "FrontLightProduct", true},
    {"gl_BackLightProduct", "FrontLightProduct", true},
    {"gl_FrontMaterial", "FrontMaterial", false},
    {"gl_BackMaterial", "FrontMaterial", false},
    {"gl_LightModel", "LightModel", false},
    {"gl_FrontLightModelProduct", "FrontLightModelProduct", false},
    {"gl_BackLightModelProduct", "FrontLightModelProduct", false},
};

const Block *blockOf(const QString &word)
{
    for (const Block &b : kBlocks)
        if (word == QLatin1String(b.name))
            return &b;
    return nullptr;
}

} // namespace

std::optional<LegacyName> legacyWord(const QString &word, ShaderStage stage)
{
    if (word == QLatin1String("ftransform"))
        return LegacyName{"(lb_ModelViewProjectionMatrix * lb_Vertex)", {}};
    for (const Word &w : kWords) {
        if (word != QLatin1String(w.name))
            continue;
        const bool vertex = stage != ShaderStage::Fragment;
        const QString replacement = QString::fromLatin1(vertex ? w.vertex : w.fragment);
        if (replacement.isEmpty())
            return std::nullopt;
        return LegacyName{
            replacement, QString::fromLatin1(vertex ? w.vertexDeclaration : w.fragmentDeclaration)};
    }
    return std::nullopt;
}

bool isLegacyBlock(const QString &word, bool &indexed)
{
    const Block *b = blockOf(word);
    indexed = b && b->indexed;
    return b != nullptr;
}

std::optional<LegacyName> legacyMember(const QString &block, const QString &member)
{
    const Block *b = blockOf(block);
    if (!b)
        return std::nullopt;
    for (const Member &m : kMembers) {
        if (QLatin1String(m.block) != QLatin1String(b->as) || member != QLatin1String(m.member))
            continue;
        const QString name = QString("lb_%1_%2").arg(QLatin1String(m.block), member);
        QString declaration;
        if (m.constant)
            declaration = QString("const %1 %2 = %3;")
                              .arg(QLatin1String(m.type), name, QLatin1String(m.constant));
        else if (b->indexed)
            declaration =
                QString("uniform %1 %2[%3];").arg(QLatin1String(m.type), name).arg(kLegacyLights);
        else
            declaration = QString("uniform %1 %2;").arg(QLatin1String(m.type), name);
        return LegacyName{name, declaration};
    }
    return std::nullopt;
}

bool usesLegacyBuiltins(const QString &source)
{
    static const QRegularExpression builtin = [] {
        QStringList names{"ftransform"};
        for (const Word &w : kWords)
            names << QString::fromLatin1(w.name);
        for (const Block &b : kBlocks)
            names << QString::fromLatin1(b.name);
        return QRegularExpression("\\b(" + names.join('|') + ")\\b");
    }();
    return builtin.match(withoutComments(source)).hasMatch();
}

QString withLegacyNames(const QString &message)
{
    QString out = message;
    for (const Block &b : kBlocks) {
        if (QLatin1String(b.name).startsWith(QLatin1String("gl_Back")))
            continue; // the front's name stands for both
        out.replace(QRegularExpression(QString("\\blb_%1_(\\w+)").arg(QLatin1String(b.as))),
                    QString("%1%2.\\1").arg(QLatin1String(b.name), b.indexed ? "[]" : ""));
    }
    // gl_Color of the fragment stage is the vertex stage's gl_FrontColor: named as written there.
    for (const Word &w : kWords)
        out.replace(QRegularExpression(QString("\\b%1\\b").arg(QLatin1String(w.vertex))),
                    QLatin1String(w.name));
    return out;
}

} // namespace lb
