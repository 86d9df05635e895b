#include "loops.h"

#include "loop_messages.h"
#include "macro_expansion.h"

#include <QLocale>
#include <QSet>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>

namespace lb {

namespace {

// What the loop reader reads: the code after the source's macros are expanded (a loop
// behind `#define FOREVER for (;;)` is read like one written out), each token on the line
// where the user wrote it or used the macro that made it.
using Token = GlslToken;

// The index of the bracket closing the one at `open`, or the end.
std::size_t closing(const std::vector<Token> &t, std::size_t open)
{
    const QString o = t[open].text;
    const QString c = o == "(" ? ")" : o == "{" ? "}" : "]";
    int depth = 0;
    for (std::size_t i = open; i < t.size(); ++i) {
        if (t[i].text == o)
            ++depth;
        else if (t[i].text == c && --depth == 0)
            return i;
    }
    return t.size();
}

// The statement starting at `i`: a block, or up to its ';' outside brackets. [begin, end).
std::pair<std::size_t, std::size_t> statementAt(const std::vector<Token> &t, std::size_t i)
{
    if (i >= t.size())
        return {t.size(), t.size()};
    if (t[i].text == "{")
        return {i, std::min(closing(t, i) + 1, t.size())};
    int depth = 0;
    for (std::size_t j = i; j < t.size(); ++j) {
        const QString &x = t[j].text;
        if (x == "(" || x == "[" || x == "{")
            ++depth;
        else if (x == ")" || x == "]" || x == "}")
            --depth;
        else if (x == ";" && depth == 0)
            return {i, j + 1};
    }
    return {i, t.size()};
}

// Functions the file defines: a name and its parameters, then a body, outside any block.
QSet<QString> definedFunctions(const std::vector<Token> &t)
{
    QSet<QString> names;
    int depth = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i].text == "{")
            ++depth;
        else if (t[i].text == "}")
            --depth;
        else if (depth == 0 && t[i].identifier && i + 1 < t.size() && t[i + 1].text == "(") {
            const std::size_t end = closing(t, i + 1);
            if (end + 1 < t.size() && t[end + 1].text == "{")
                names.insert(t[i].text);
        }
    }
    return names;
}

bool isAssignment(const QString &x)
{
    static const QSet<QString> ops{
        "=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="};
    return ops.contains(x);
}

// The variable an lvalue ending at `j` (inclusive) belongs to: v, v.x, v[i], v[i].xy.
QString baseBefore(const std::vector<Token> &t, std::size_t j)
{
    std::size_t k = j + 1;
    while (k-- > 0) {
        if (t[k].text == "]") {
            int depth = 0;
            for (; k > 0; --k) {
                if (t[k].text == "]")
                    ++depth;
                else if (t[k].text == "[" && --depth == 0)
                    break;
            }
            continue;
        }
        if (t[k].identifier) {
            if (k > 0 && t[k - 1].text == ".") {
                --k; // the member and its dot; the base comes before them
                continue;
            }
            return t[k].text;
        }
        return {};
    }
    return {};
}

// What a stretch of tokens writes to: assigned, incremented or decremented names.
void collectChanged(const std::vector<Token> &t, std::size_t begin, std::size_t end,
                    QSet<QString> &changed)
{
    for (std::size_t j = begin; j < end; ++j) {
        const QString &x = t[j].text;
        if (isAssignment(x) && j > begin) {
            changed.insert(baseBefore(t, j - 1));
        } else if (x == "++" || x == "--") {
            if (j + 1 < end && t[j + 1].identifier)
                changed.insert(t[j + 1].text); // prefix
            if (j > begin)
                changed.insert(baseBefore(t, j - 1)); // postfix
        } else if (t[j].identifier && j + 1 < end && t[j + 1].identifier && j + 2 < end &&
                   (t[j + 2].text == "=" || t[j + 2].text == ";")) {
            changed.insert(t[j + 1].text); // a declaration in the loop makes a new variable
        }
    }
}

bool exits(const std::vector<Token> &t, std::size_t begin, std::size_t end)
{
    return std::any_of(t.begin() + long(begin), t.begin() + long(end), [](const Token &x) {
        return x.text == "break" || x.text == "return" || x.text == "discard";
    });
}

bool callsAny(const std::vector<Token> &t, std::size_t begin, std::size_t end,
              const QSet<QString> &functions)
{
    for (std::size_t j = begin; j + 1 < end; ++j)
        if (t[j].identifier && t[j + 1].text == "(" && functions.contains(t[j].text))
            return true;
    return false;
}

bool alwaysTrue(const std::vector<Token> &t, std::size_t begin, std::size_t end)
{
    QStringList words;
    for (std::size_t j = begin; j < end; ++j)
        if (t[j].text != "(" && t[j].text != ")")
            words << t[j].text;
    if (words.size() != 1)
        return false;
    if (words[0] == "true")
        return true;
    QString digits = words[0]; // 1, 1.0, 1u, 1.0f
    if (digits.endsWith('u') || digits.endsWith('f') || digits.endsWith('F'))
        digits.chop(1);
    bool number = false;
    const double value = digits.toDouble(&number);
    return number && value != 0.0;
}

// The names a condition reads (not function names, not members after a dot).
QStringList namesRead(const std::vector<Token> &t, std::size_t begin, std::size_t end)
{
    static const QSet<QString> words{"true", "false"};
    QStringList names;
    for (std::size_t j = begin; j < end; ++j) {
        if (!t[j].identifier || words.contains(t[j].text))
            continue;
        if (j + 1 < end && t[j + 1].text == "(")
            continue; // a call or a constructor
        if (j > begin && t[j - 1].text == ".")
            continue; // a member
        if (!names.contains(t[j].text))
            names << t[j].text;
    }
    return names;
}

// The semicolons that split a for's parentheses [open, close] into its three parts.
std::vector<std::size_t> forSemicolons(const std::vector<Token> &t, std::size_t open,
                                       std::size_t close)
{
    std::vector<std::size_t> semis;
    int depth = 0;
    for (std::size_t j = open + 1; j < close; ++j) {
        if (t[j].text == "(")
            ++depth;
        else if (t[j].text == ")")
            --depth;
        else if (t[j].text == ";" && depth == 0)
            semis.push_back(j);
    }
    return semis;
}

// An integer literal's value ("1000000000", "0x10", "5u"); nullopt for anything else. (A
// #define'd bound is read too: the loop reader reads the expanded code.)
std::optional<double> integerLiteral(const Token &t)
{
    QString digits = t.text;
    if (digits.endsWith('u') || digits.endsWith('U'))
        digits.chop(1);
    bool ok = false;
    const qlonglong v = digits.toLongLong(&ok, 0);
    return ok ? std::optional<double>(double(v)) : std::nullopt;
}

bool isUnsignedLiteral(const Token &t)
{
    return t.text.endsWith('u') || t.text.endsWith('U');
}

// How many times `for (int i = A; i < B; i++)` runs, read from its three parts when they are
// that simple: a literal start and bound, a comparison of the counter with the bound (<, <=,
// !=, >, >=), and a literal step (++, --, += C, -= C). nullopt for anything else. A counter
// that moves away from its bound (`i >= 0; i++`) runs until it wraps around (GLSL's integers
// do: 2^31 steps for an int), and `wraps` says so.
std::optional<double> countedSteps(const std::vector<Token> &t, std::size_t ib, std::size_t ie,
                                   std::size_t cb, std::size_t ce, std::size_t sb, std::size_t se,
                                   bool *wraps = nullptr)
{
    // init: [int|uint] i = A
    bool isUnsigned = false;
    if (ie > ib && (t[ib].text == "int" || t[ib].text == "uint"))
        isUnsigned = t[ib++].text == "uint";
    if (ie - ib != 3 || !t[ib].identifier || t[ib + 1].text != "=")
        return std::nullopt;
    const QString counter = t[ib].text;
    const std::optional<double> start = integerLiteral(t[ib + 2]);
    // condition: i < B
    if (ce - cb != 3 || t[cb].text != counter)
        return std::nullopt;
    const QString comparison = t[cb + 1].text;
    const std::optional<double> bound = integerLiteral(t[cb + 2]);
    isUnsigned = isUnsigned || isUnsignedLiteral(t[ib + 2]) || isUnsignedLiteral(t[cb + 2]);
    // step: i++, ++i, i--, --i, i += C, i -= C
    double step = 0.0;
    if (se - sb == 2 && (t[sb].text == counter || t[sb + 1].text == counter)) {
        const QString op = t[sb].text == counter ? t[sb + 1].text : t[sb].text;
        step = op == "++" ? 1.0 : op == "--" ? -1.0 : 0.0;
    } else if (se - sb == 3 && t[sb].text == counter) {
        const std::optional<double> c = integerLiteral(t[sb + 2]);
        if (c)
            step = t[sb + 1].text == "+=" ? *c : t[sb + 1].text == "-=" ? -*c : 0.0;
    }
    if (!start || !bound || step == 0.0)
        return std::nullopt;
    const double span = *bound - *start;
    const bool upwards = comparison == "<" || comparison == "<=";
    const bool holds = comparison == "<"    ? span > 0
                       : comparison == "<=" ? span >= 0
                       : comparison == ">"  ? span < 0
                       : comparison == ">=" ? span <= 0
                                            : false;
    if (holds && (upwards ? step < 0 : (comparison == ">" || comparison == ">=") && step > 0)) {
        if (isUnsigned && comparison == ">=" && *bound == 0)
            return std::nullopt; // never false; not counted
        if (wraps)
            *wraps = true;
        const double wrap = isUnsigned ? 4294967296.0 : 2147483648.0;
        return step > 0 ? std::floor((wrap - 1 - *start) / step) + 1
                        : std::floor((isUnsigned ? *start : *start + 2147483648.0) / -step) + 1;
    }
    if (comparison == "<" || comparison == "!=")
        return step > 0 && span > 0 ? std::ceil(span / step) : std::optional<double>();
    if (comparison == "<=")
        return step > 0 && span >= 0 ? std::floor(span / step) + 1 : std::optional<double>();
    if (comparison == ">")
        return step < 0 && span < 0 ? std::ceil(span / step) : std::optional<double>();
    if (comparison == ">=")
        return step < 0 && span <= 0 ? std::floor(span / step) + 1 : std::optional<double>();
    return std::nullopt;
}

} // namespace

namespace {

// A counted loop this long is as good as endless: even at a nanosecond a step, a million
// fragments would take hours.
constexpr double kEndlessSteps = 1e7;

struct EndlessLoop
{
    Diagnostic warning;
    QString refusal; // the program's, for a loop certain never to end (no condition, always
                     // true, or as good as endless); empty for the others
};

std::vector<EndlessLoop> endlessLoops(const QString &source, ShaderStage stage)
{
    const MacroExpansion tokens = expandMacros(source, stage);
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

std::vector<Diagnostic> endlessLoopWarnings(const QString &source, ShaderStage stage)
{
    std::vector<Diagnostic> out;
    for (const EndlessLoop &l : endlessLoops(source, stage))
        out.push_back(l.warning);
    return out;
}

std::vector<Diagnostic> certainEndlessLoops(const QString &source, ShaderStage stage,
                                            bool asRefusals)
{
    std::vector<Diagnostic> out;
    for (const EndlessLoop &l : endlessLoops(source, stage))
        if (!l.refusal.isEmpty()) {
            out.push_back(l.warning);
            if (asRefusals) {
                out.back().severity = Diagnostic::Severity::Error;
                out.back().message = l.refusal;
            }
        }
    return out;
}

bool onlyShortLoops(const QString &source, int maxSteps)
{
    const MacroExpansion tokens = expandMacros(source);
    const std::vector<Token> &t = tokens.tokens;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const QString &k = t[i].text;
        const bool opens = i + 1 < t.size() && t[i + 1].text == "(";
        if (k == "do" || (k == "while" && opens))
            return false;
        if (k != "for" || !opens)
            continue;
        const std::size_t close = closing(t, i + 1);
        const std::vector<std::size_t> semis = forSemicolons(t, i + 1, close);
        if (semis.size() != 2)
            return false;
        const std::optional<double> steps =
            countedSteps(t, i + 2, semis[0], semis[0] + 1, semis[1], semis[1] + 1, close);
        if (!steps || *steps > maxSteps)
            return false;
    }
    return true;
}

std::vector<SourcePlace> loopPlaces(const QString &source)
{
    const std::vector<Token> t = expandMacros(source).tokens;
    std::vector<SourcePlace> places;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const QString &k = t[i].text;
        const bool opens = i + 1 < t.size() && t[i + 1].text == "(";
        if (k == "do" || ((k == "for" || k == "while") && opens))
            places.push_back({t[i].line, t[i].column});
    }
    return places;
}

} // namespace lb
