#include "webgl1_translation.h"

#include "glsl_lexer.h"
#include "legacy_builtins.h"

#include <QHash>

#include <atomic>

namespace lb {

namespace {

std::atomic<int> g_forced{-1}; // -1: not set, read the environment
std::atomic<bool> g_driverRefuses{false};

const QHash<QString, QString> &commonNames()
{
    static const QHash<QString, QString> names = [] {
        QHash<QString, QString> h{
            {"texture2D", "texture"},
            {"texture2DProj", "textureProj"},
            {"texture2DLod", "textureLod"},
            {"texture2DLodEXT", "textureLod"},
            {"texture2DProjLod", "textureProjLod"},
            {"texture2DProjLodEXT", "textureProjLod"},
            {"textureCube", "texture"},
            {"textureCubeLod", "textureLod"},
            {"textureCubeLodEXT", "textureLod"},
            {"gl_FragDepthEXT", "gl_FragDepth"},
        };
        // Words of GLSL 3.30 that a GLSL ES 1.00 shader may use as its own names.
        for (const char *word : {"texture",
                                 "flat",
                                 "smooth",
                                 "noperspective",
                                 "layout",
                                 "centroid",
                                 "uint",
                                 "uvec2",
                                 "uvec3",
                                 "uvec4",
                                 "isampler2D",
                                 "usampler2D",
                                 "sampler2DRect",
                                 "samplerBuffer",
                                 "sampler1D",
                                 "sampler3D",
                                 "sampler2DShadow",
                                 "sampler1DShadow",
                                 "case",
                                 "default",
                                 "switch"})
            h.insert(word, QString("lb_") + word);
        return h;
    }();
    return names;
}

// Spaces and tabs from `i` on (a newline ends the skip, so that lines stay where they are).
int skipBlanks(const QString &source, int i)
{
    while (i < source.size() && (source[i] == ' ' || source[i] == '\t'))
        ++i;
    return i;
}

int identifierEnd(const QString &source, int i)
{
    while (i < source.size() && (source[i].isLetterOrNumber() || source[i] == '_'))
        ++i;
    return i;
}

// A fixed-function built-in at `word` (legacy_builtins.h) written as its 3.30 name into `out`,
// its declarations added to `declarations`; the end of what it replaced, or -1 for a word
// that is none (or a block not followed by [index].member, left for the driver).
int translateLegacyWord(const QString &source, int wordEnd, const QString &word, ShaderStage stage,
                        QString &out, QStringList &declarations)
{
    const auto declare = [&](const QString &declaration) {
        if (!declaration.isEmpty() && !declarations.contains(declaration))
            declarations << declaration;
    };
    bool indexed = false;
    if (isLegacyBlock(word, indexed)) {
        int j = skipBlanks(source, wordEnd);
        QString index;
        if (indexed) {
            if (j >= source.size() || source[j] != '[')
                return -1;
            // An index is short: a longer one (or none closed on its line) is left for the
            // driver, and no run of "gl_LightSource[" scans the rest of its line each time.
            constexpr int kLongestIndex = 256;
            int depth = 0, close = j;
            for (; close < source.size() && close - j < kLongestIndex; ++close) {
                depth += source[close] == '[' ? 1 : source[close] == ']' ? -1 : 0;
                if (depth == 0 || source[close] == '\n')
                    break;
            }
            if (close >= source.size() || close - j >= kLongestIndex || source[close] != ']')
                return -1;
            index = source.mid(j + 1, close - j - 1);
            j = skipBlanks(source, close + 1);
        }
        if (j >= source.size() || source[j] != '.')
            return -1;
        const int memberStart = skipBlanks(source, j + 1);
        const int memberEnd = identifierEnd(source, memberStart);
        const std::optional<LegacyName> member =
            legacyMember(word, source.mid(memberStart, memberEnd - memberStart));
        if (!member)
            return -1;
        out += member->replacement + (indexed ? "[" + index + "]" : QString());
        declare(member->declaration);
        return memberEnd;
    }
    const std::optional<LegacyName> name = legacyWord(word, stage);
    if (!name)
        return -1;
    if (word == QLatin1String("ftransform")) {
        const int open = skipBlanks(source, wordEnd);
        const int close =
            open < source.size() && source[open] == '(' ? skipBlanks(source, open + 1) : -1;
        if (close < 0 || close >= source.size() || source[close] != ')')
            return -1;
        for (const char *used : {"gl_ModelViewProjectionMatrix", "gl_Vertex"})
            declare(legacyWord(used, stage)->declaration);
        out += name->replacement;
        return close + 1;
    }
    out += name->replacement;
    declare(name->declaration);
    return wordEnd;
}

TranslatedSource translate(const QString &source, ShaderStage stage, bool legacy)
{
    const bool fragment = stage == ShaderStage::Fragment;
    QHash<QString, QString> names = commonNames();
    names.insert("attribute", "in");
    names.insert("varying", fragment ? "in" : "out");
    if (fragment) {
        names.insert("gl_FragColor", "lb_FragColor");
        names.insert("gl_FragData", "lb_FragData");
    }
    bool usesFragColor = false, usesFragData = false;
    QStringList declarations; // the legacy built-ins' (legacy_builtins.h)

    QString out;
    out.reserve(source.size() + 64);
    const int n = int(source.size());
    bool lineHasCode = false;
    for (int i = 0; i < n;) {
        const QChar c = source[i];
        if (c == '\n') {
            out += c;
            ++i;
            lineHasCode = false;
            continue;
        }
        if (c == '/' && i + 1 < n && (source[i + 1] == '/' || source[i + 1] == '*')) {
            const bool block = source[i + 1] == '*';
            const int end = block ? source.indexOf("*/", i + 2) : source.indexOf('\n', i);
            const int stop = end < 0 ? n : (block ? end + 2 : end);
            out += source.mid(i, stop - i);
            i = stop;
            continue;
        }
        if (c == '#' && !lineHasCode) {
            // A directive: #version 100 and #extension lines go (blank, the line kept);
            // the others are kept, names inside them translated like the code.
            int end = i;
            while (end < n && source[end] != '\n' &&
                   !(source[end] == '/' && end + 1 < n &&
                     (source[end + 1] == '/' || source[end + 1] == '*')))
                ++end;
            const QString directive = source.mid(i + 1, end - i - 1).simplified();
            if (directive.startsWith("version") || directive.startsWith("extension")) {
                i = end;
                continue;
            }
        }
        if (!c.isSpace())
            lineHasCode = true;
        if (startsIdentifier(c)) {
            const int end = identifierEnd(source, i);
            const QString word = source.mid(i, end - i);
            if (legacy) {
                const int replaced =
                    translateLegacyWord(source, end, word, stage, out, declarations);
                if (replaced >= 0) {
                    i = replaced;
                    continue;
                }
            }
            usesFragColor |= fragment && word == "gl_FragColor";
            usesFragData |= fragment && word == "gl_FragData";
            out += names.value(word, word);
            i = end;
            continue;
        }
        if (c.isDigit()) { // a number's letters (1e5, 0x1F, 2u) are no names
            int end = i;
            while (end < n && (source[end].isLetterOrNumber() || source[end] == '.'))
                ++end;
            out += source.mid(i, end - i);
            i = end;
            continue;
        }
        out += c;
        ++i;
    }

    // The header: the version, then one line declaring the outputs (empty if none).
    QString outputs;
    if (usesFragColor)
        outputs += "out vec4 lb_FragColor;";
    if (usesFragData)
        outputs += " out vec4 lb_FragData[gl_MaxDrawBuffers];";
    outputs += " " + declarations.join(' ');
    return {"#version 330 core\n" + outputs.trimmed() + "\n" + out, 2};
}

} // namespace

TranslatedSource translateWebGl1(const QString &source, ShaderStage stage)
{
    return translate(source, stage, false);
}

TranslatedSource translateLegacyGlsl(const QString &source, ShaderStage stage)
{
    return translate(source, stage, true);
}

bool webGl1TranslationForced()
{
    int forced = g_forced.load();
    if (forced < 0) {
        forced = qEnvironmentVariable("LIGHTBENCH_TRANSLATE_WEBGL1") == "1" ? 1 : 0;
        g_forced = forced;
    }
    return forced == 1;
}

void setWebGl1TranslationForced(bool forced)
{
    g_forced = forced ? 1 : 0;
}

void noteDriverRefusesVersion100(bool refuses)
{
    g_driverRefuses = refuses;
}

bool translatesWebGl1()
{
    return webGl1TranslationForced() || g_driverRefuses.load();
}

} // namespace lb
