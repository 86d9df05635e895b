#include "dialect.h"

#include "legacy_builtins.h"
#include "webgl1_translation.h"

#include <QRegularExpression>

namespace lb {

// Blanks out comments so that a "#version" inside one is not taken for the directive.
QString withoutComments(const QString &source)
{
    QString out = source;
    for (int i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n')
                out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            const int end = out.indexOf("*/", i + 2);
            const int stop = end < 0 ? out.size() : end + 2;
            for (; i < stop; ++i)
                if (out[i] != '\n')
                    out[i] = ' ';
        }
    }
    return out;
}

bool writesFragmentColour(const QString &fragmentSource)
{
    static const QRegularExpression writes(R"(\bgl_Frag(Color|Data)\b|(^|[;\s)])out\s+\w+\s+\w+)");
    return writes.match(withoutComments(fragmentSource)).hasMatch();
}

PreparedSource prepareSource(const QString &source)
{
    static const QRegularExpression directive(R"(^[ \t]*#[ \t]*version[ \t]+([^\n]*?)[ \t]*$)",
                                              QRegularExpression::MultilineOption);
    PreparedSource p;
    const QRegularExpressionMatch m = directive.match(withoutComments(source));
    if (m.hasMatch()) {
        p.text = source;
        p.version = m.captured(1).simplified();
        return p;
    }
    p.dialect = Dialect::WebGL1Implicit;
    p.version = "100";
    p.text = "#version 100\n" + source;
    p.linesAdded = 1;
    return p;
}

PreparedSource prepareSource(const QString &source, ShaderStage stage, bool translateWebGl1)
{
    PreparedSource p = prepareSource(source);
    if (!translateWebGl1 || p.version != "100")
        return p;
    const TranslatedSource t = lb::translateWebGl1(source, stage);
    p.text = t.text;
    p.linesAdded = t.linesAdded;
    p.dialect = Dialect::WebGL1Translated;
    p.version = "330 core";
    return p;
}

PreparedSource prepareLegacySource(const QString &source, ShaderStage stage)
{
    const TranslatedSource t = translateLegacyGlsl(source, stage);
    PreparedSource p;
    p.text = t.text;
    p.linesAdded = t.linesAdded;
    p.dialect = Dialect::LegacyTranslated;
    p.version = "330 core";
    return p;
}

bool legacyProgram(const QString &vertexSource, const QString &fragmentSource)
{
    for (const QString *source : {&vertexSource, &fragmentSource}) {
        const QString version = prepareSource(*source).version;
        if (version != "100" && version != "110" && version != "120" && version != "130")
            return false;
    }
    return usesLegacyBuiltins(vertexSource) || usesLegacyBuiltins(fragmentSource);
}

} // namespace lb
