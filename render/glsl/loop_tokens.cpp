#include "loop_tokens.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace lb::looptokens {

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
                                   bool *wraps)
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

} // namespace lb::looptokens
