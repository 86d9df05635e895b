#pragma once
// The lighting equation as the course writes it, with a probed point's numbers put in, term
// by term and light by light: what the Probe panel shows and copies as text.

#include "probe.h"
#include "scene.h"

#include <QString>

#include <vector>

namespace lb {

// A piece of a line: symbols and numbers as they are, a phrase of words (the Probe panel shows
// it translated, context lb::ProbeEquation), or a Show choice's file word (shown as the Shading
// panel names the choice). `before` and `after` stand beside it as they are (spaces).
struct EquationPart
{
    enum class Kind { Symbols, Phrase, ShowChoice };
    Kind kind = Kind::Symbols;
    QString text; // English
    QString before = {}, after = {};
    // `text` as shown (English or translated) with what stands beside it; none for no text.
    QString beside(const QString &shown) const
    {
        return text.isEmpty() ? QString() : before + shown + after;
    }
};

// One line: a pattern whose %1, %2, ... are its parts, in English. `words`: the pattern has
// words (marked for lupdate in lb::ProbeEquation), else symbols only, the same in every language.
struct EquationLine
{
    const char *pattern;
    std::vector<EquationPart> parts;
    bool words = false;
};

// Each %N of `pattern` replaced by `parts[N - 1]`, in one pass (a part's own % stays).
QString fillPattern(const QString &pattern, const QStringList &parts);
// The line in English, as the command line prints it and Copy the Equation copies it.
QString equationLineText(const EquationLine &line);

// The equation in symbols (the specular model's cosine, only the terms switched on), then each
// light that is on with its numbers, then the sum and the pixel it gives, and what the picture
// shows instead where that differs. None when `probe` missed the surface.
std::vector<EquationLine> lightingEquationLines(const Scene &scene, const ProbeResult &probe);
// Those lines in English, one a line.
QString lightingEquation(const Scene &scene, const ProbeResult &probe);

} // namespace lb
