#include "glsl_lexer.h"

#include <QFont>
#include <QFontDatabase>

namespace lb {

namespace {

// Keywords, qualifiers and types (set 1: bold blue).
const char *kKeywords =
    "attribute const uniform varying buffer shared layout centroid flat smooth noperspective "
    "patch sample break continue do for while switch case default if else subroutine in out "
    "inout float double int void bool true false invariant precise discard return mat2 mat3 "
    "mat4 dmat2 dmat3 dmat4 mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 vec2 "
    "vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 dvec2 dvec3 dvec4 uint uvec2 uvec3 uvec4 "
    "lowp mediump highp precision sampler1D sampler2D sampler3D samplerCube sampler2DShadow "
    "samplerCubeShadow sampler2DArray isampler2D usampler2D struct";

// Built-in functions and variables (set 2).
const char *kBuiltIns =
    "radians degrees sin cos tan asin acos atan sinh cosh tanh pow exp log exp2 log2 sqrt "
    "inversesqrt abs sign floor trunc round ceil fract mod modf min max clamp mix step "
    "smoothstep isnan isinf length distance dot cross normalize faceforward reflect refract "
    "matrixCompMult outerProduct transpose determinant inverse lessThan lessThanEqual "
    "greaterThan greaterThanEqual equal notEqual any all not texture texture2D textureCube "
    "texture2DProj textureLod texelFetch textureSize dFdx dFdy fwidth gl_Position gl_PointSize "
    "gl_FragColor gl_FragData gl_FragCoord gl_FrontFacing gl_PointCoord gl_VertexID "
    "gl_InstanceID gl_FragDepth";

} // namespace

GlslLexer::GlslLexer(QObject *parent) : QsciLexerCPP(parent)
{
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    setDefaultFont(mono);
    setFont(mono);
    setColor(QColor("#0033aa"), Keyword);
    setColor(QColor("#7a2e9e"), KeywordSet2);
    setColor(QColor("#6a737d"), Comment);
    setColor(QColor("#6a737d"), CommentLine);
    setColor(QColor("#a04000"), Number);
    setColor(QColor("#8a5a00"), PreProcessor);
    QFont bold = mono;
    bold.setBold(true);
    setFont(bold, Keyword);
}

const char *GlslLexer::keywords(int set) const
{
    if (set == 1)
        return kKeywords;
    if (set == 2)
        return kBuiltIns;
    return nullptr;
}

const QStringList &GlslLexer::completionWords()
{
    static const QStringList words =
        (QString(kKeywords) + ' ' + kBuiltIns).split(' ', Qt::SkipEmptyParts);
    return words;
}

} // namespace lb
