#include "loops.h"

#include "loop_messages.h"
#include "loop_tokens.h"
#include "macro_expansion.h"

#include <QLocale>
#include <QSet>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>

namespace lb {

using namespace looptokens;

namespace {

// A counted loop this long is as good as endless: even at a nanosecond a step, a million
// fragments would take hours.
constexpr double kEndlessSteps = 1e7;

using EndlessLoop = LoopReading::Endless;

std::vector<EndlessLoop> endlessLoops(const MacroExpansion &tokens, ShaderStage stage)
{
    const std::vector<Token> &t = tokens.tokens;
    const QSet<QString> functions = definedFunctions(t);
    std::vector<EndlessLoop> out;
    QSet<std::size_t> doWhiles; // the `while` of a do-loop, read with its `do`
    auto warn = [&](const Token &at, const LoopTexts &texts) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.stage = stage;
        d.line = at.line;
        d.column = at.column;
        LoopTexts said = texts;
        if (!at.macro.isEmpty()) // the user sees the use, not the macro's text
            for (QString *text : {&said.warning, &said.refusal})
                *text = text->isEmpty() ? *text : withMacroNote(*text, at.macro);
        d.message = said.warning;
        out.push_back({d, said.refusal});
    };
    // One loop: its condition [cb, ce) (empty: none), what runs each time [bb, be) and the
    // for's step [sb, se).
    auto judge = [&](const Token &at, std::size_t cb, std::size_t ce, std::size_t bb,
                     std::size_t be, std::size_t sb, std::size_t se, std::size_t ib = 0,
                     std::size_t ie = 0) {
        if (exits(t, bb, be))
            return;
        // A loop the preprocessor may leave out, or one with a macro's name left unexpanded
        // in it (it may hide a break or a step), is not read.
        auto unsure = [&](std::size_t b, std::size_t e) {
            for (std::size_t j = b; j < std::min(e, t.size()); ++j)
                if (t[j].conditional || tokens.macros.contains(t[j].text))
                    return true;
            return false;
        };
        if (at.conditional || unsure(cb, ce) || unsure(bb, be) || unsure(sb, se))
            return;
        bool wraps = false;
        if (const std::optional<double> steps = countedSteps(t, ib, ie, cb, ce, sb, se, &wraps);
            steps && *steps >= kEndlessSteps) {
            const QString count = QLocale(QLocale::English).toString(qlonglong(*steps));
            warn(at, countedLoopTexts(count, stage, wraps));
            return;
        }
        if (cb == ce || alwaysTrue(t, cb, ce)) {
            warn(at, unconditionalLoopTexts(cb == ce));
            return;
        }
        if (callsAny(t, bb, be, functions) || callsAny(t, sb, se, functions) ||
            callsAny(t, cb, ce, functions))
            return; // a function of the file could change what the condition reads
        const QStringList read = namesRead(t, cb, ce);
        if (read.isEmpty())
            return;
        QSet<QString> changed;
        collectChanged(t, bb, be, changed);
        collectChanged(t, sb, se, changed);
        collectChanged(t, cb, ce, changed); // while (i++ < 10)
        for (const QString &name : read)
            if (changed.contains(name))
                return;
        warn(at, {unchangedConditionWarning(read), {}});
    };

    for (std::size_t i = 0; i < t.size(); ++i) {
        const QString &k = t[i].text;
        if (k == "for" && i + 1 < t.size() && t[i + 1].text == "(") {
            const std::size_t close = closing(t, i + 1);
            const std::vector<std::size_t> semis = forSemicolons(t, i + 1, close);
            if (semis.size() != 2)
                continue;
            const auto body = statementAt(t, close + 1);
            judge(t[i], semis[0] + 1, semis[1], body.first, body.second, semis[1] + 1, close, i + 2,
                  semis[0]);
        } else if (k == "while" && !doWhiles.contains(i) && i + 1 < t.size() &&
                   t[i + 1].text == "(") {
            const std::size_t close = closing(t, i + 1);
            const auto body = statementAt(t, close + 1);
            judge(t[i], i + 2, close, body.first, body.second, 0, 0);
        } else if (k == "do") {
            const auto body = statementAt(t, i + 1);
            const std::size_t w = body.second;
            if (w + 1 >= t.size() || t[w].text != "while" || t[w + 1].text != "(")
                continue;
            doWhiles.insert(w);
            judge(t[i], w + 2, closing(t, w + 1), body.first, body.second, 0, 0);
        }
    }
    return out;
}

} // namespace

namespace {

// The loops' places, and whether each is a counted for (and how long).
void readPlaces(const std::vector<Token> &t, LoopReading &reading)
{
    for (std::size_t i = 0; i < t.size(); ++i) {
        const QString &k = t[i].text;
        const bool opens = i + 1 < t.size() && t[i + 1].text == "(";
        if (k != "do" && !((k == "for" || k == "while") && opens))
            continue;
        reading.places.push_back({t[i].line, t[i].column});
        if (k != "for") {
            reading.onlyCounted = false;
            continue;
        }
        const std::size_t close = closing(t, i + 1);
        const std::vector<std::size_t> semis = forSemicolons(t, i + 1, close);
        const std::optional<double> steps =
            semis.size() == 2
                ? countedSteps(t, i + 2, semis[0], semis[0] + 1, semis[1], semis[1] + 1, close)
                : std::nullopt;
        if (steps)
            reading.longestCounted = std::max(reading.longestCounted, *steps);
        else
            reading.onlyCounted = false;
    }
}

LoopReading readNow(const QString &source, ShaderStage stage)
{
    const MacroExpansion tokens = expandMacros(source, stage);
    LoopReading reading;
    if (tokens.refusal) {
        reading.expansionRefusal = tokens.refusal;
        reading.onlyCounted = false;
        return reading;
    }
    reading.endless = endlessLoops(tokens, stage);
    readPlaces(tokens.tokens, reading);
    return reading;
}

} // namespace

LoopReading readLoops(const QString &source, ShaderStage stage)
{
    // The last few texts read, newest first: one program's two stages, and the one before.
    // A reading holds its messages in the language installed when it was read: one of them,
    // as the catalogue says it now, is part of the key, so a new catalogue reads again.
    struct Kept
    {
        QString source;
        ShaderStage stage;
        QString language;
        LoopReading reading;
    };
    constexpr std::size_t kKept = 4;
    thread_local std::vector<Kept> kept;
    const QString language = unconditionalLoopTexts(true).warning;
    for (std::size_t i = 0; i < kept.size(); ++i)
        if (kept[i].stage == stage && kept[i].language == language && kept[i].source == source) {
            std::rotate(kept.begin(), kept.begin() + std::ptrdiff_t(i),
                        kept.begin() + std::ptrdiff_t(i) + 1);
            return kept.front().reading;
        }
    kept.insert(kept.begin(), Kept{source, stage, language, readNow(source, stage)});
    if (kept.size() > kKept)
        kept.pop_back();
    return kept.front().reading;
}

std::vector<Diagnostic> endlessLoopWarnings(const QString &source, ShaderStage stage)
{
    std::vector<Diagnostic> out;
    for (const EndlessLoop &l : readLoops(source, stage).endless)
        out.push_back(l.warning);
    return out;
}

std::vector<Diagnostic> certainEndlessLoops(const QString &source, ShaderStage stage,
                                            bool asRefusals)
{
    std::vector<Diagnostic> out;
    for (const EndlessLoop &l : readLoops(source, stage).endless)
        if (!l.refusal.isEmpty()) {
            out.push_back(l.warning);
            if (asRefusals) {
                out.back().severity = Diagnostic::Severity::Error;
                out.back().message = l.refusal;
            }
        }
    return out;
}

bool onlyShortLoops(const QString &source, int maxSteps, ShaderStage stage)
{
    const LoopReading reading = readLoops(source, stage);
    return reading.onlyCounted && reading.longestCounted <= maxSteps;
}

std::vector<SourcePlace> loopPlaces(const QString &source, ShaderStage stage)
{
    return readLoops(source, stage).places;
}

} // namespace lb
