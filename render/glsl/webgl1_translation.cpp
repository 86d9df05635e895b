#include "webgl1_translation.h"

#include "glsl_lexer.h"

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

} // namespace

TranslatedSource translateWebGl1(const QString &source, ShaderStage stage)
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
            int end = i;
            while (end < n && (source[end].isLetterOrNumber() || source[end] == '_'))
                ++end;
            const QString word = source.mid(i, end - i);
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
    return {"#version 330 core\n" + outputs.trimmed() + "\n" + out, 2};
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
