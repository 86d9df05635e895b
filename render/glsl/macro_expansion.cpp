#include "macro_expansion.h"

#include "macro_token_reader.h"

#include <QCoreApplication>
#include <QHash>
#include <QStringList>

#include <algorithm>

namespace lb {

namespace {

using macro_tokens::Pending;
using macro_tokens::Reader;
using macro_tokens::Use;

struct Macro
{
    QString name;
    bool functionLike = false;
    QStringList parameters;
    std::vector<GlslToken> body;
    bool conditional = false; // defined inside #if...: maybe not defined at all
};

bool isIdentifier(const QString &text)
{
    if (text.isEmpty() || !startsIdentifier(text[0]))
        return false;
    return std::all_of(text.begin(), text.end(),
                       [](QChar c) { return c.isLetterOrNumber() || c == '_'; });
}

class Expander
{
    Q_DECLARE_TR_FUNCTIONS(lb::MacroExpansion)
public:
    explicit Expander(ShaderStage stage) : m_stage(stage) {}
    MacroExpansion run(const QString &source);

private:
    void expand(Reader &in, std::vector<Pending> &out, int depth);
    std::optional<std::vector<Pending>> replace(int index, const Pending &use, Reader &in,
                                                int depth);
    bool collectArguments(Reader &in, std::vector<std::vector<Pending>> &arguments,
                          std::vector<Pending> &taken);
    void directive(const std::vector<Pending> &list, std::size_t begin, std::size_t end);
    void define(const std::vector<Pending> &list, std::size_t begin, std::size_t end);
    void expandExpression(const std::vector<Pending> &list, std::size_t begin, std::size_t end);
    void output(std::vector<Pending> &out, Pending &&p, int depth);
    bool hides(int node, int macro) const;
    int hideAlso(int node, int macro);
    bool spend(long long tokens);
    // `message`: a whole sentence (QT_TR_NOOP) with %1 the macro used, %2 `limit`.
    void refuse(const char *message, int limit = 0);

    ShaderStage m_stage;
    std::vector<Macro> m_macros;   // every definition, in order
    QHash<QString, int> m_defined; // name -> its definition now
    struct HiddenNode
    {
        int macro, parent, length; // the macro, the node it adds to, how many in all
    };
    std::vector<HiddenNode> m_hidden;
    QHash<quint64, int> m_hiddenNodes; // (node, macro) -> the node made of both
    long long m_made = 0, m_characters = 0;
    int m_conditionalDepth = 0;
    std::vector<Use> m_uses;
    int m_use = -1; // the use being expanded at the top (the refusal's place)
    MacroExpansion m_result;
};

bool Expander::hides(int node, int macro) const
{
    for (; node >= 0; node = m_hidden[std::size_t(node)].parent)
        if (m_hidden[std::size_t(node)].macro == macro)
            return true;
    return false;
}

int Expander::hideAlso(int node, int macro)
{
    if (hides(node, macro))
        return node;
    const quint64 key = (quint64(quint32(node + 1)) << 32) | quint32(macro);
    if (const auto it = m_hiddenNodes.constFind(key); it != m_hiddenNodes.constEnd())
        return *it;
    // A chain of macros each expanding to the next (`#define A1 A0`, `#define A2 A1`...)
    // makes these sets as long as it: bounded, so that each look-up is.
    const int length = node < 0 ? 1 : m_hidden[std::size_t(node)].length + 1;
    if (length > kMaxMacroNesting) {
        refuse(QT_TR_NOOP("macro %1 expands through more than %2 macros, one inside another: "
                          "refused before the driver sees it"),
               kMaxMacroNesting);
        return node;
    }
    m_hidden.push_back({macro, node, length});
    const int made = int(m_hidden.size()) - 1;
    m_hiddenNodes.insert(key, made);
    return made;
}

void Expander::refuse(const char *message, int limit)
{
    if (m_result.refusal)
        return;
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.stage = m_stage;
    const Use &use = m_uses[std::size_t(m_use)];
    d.line = use.line;
    d.column = use.column;
    d.message = limit ? tr(message).arg(use.macro).arg(limit) : tr(message).arg(use.macro);
    m_result.refusal = d;
}

bool Expander::spend(long long tokens)
{
    m_made += tokens;
    if (m_made > kMaxMacroTokens)
        refuse(QT_TR_NOOP("macro %1 expands to more than a million tokens (a macro that doubles "
                          "itself?): refused before the driver sees it"));
    return !m_result.refusal;
}

void Expander::output(std::vector<Pending> &out, Pending &&p, int depth)
{
    if (depth == 0 && p.use >= 0) {
        const Use &use = m_uses[std::size_t(p.use)];
        p.token.line = use.line;
        p.token.column = use.column;
        p.token.macro = use.macro;
        m_characters += p.token.text.size() + 1;
        if (m_characters > kMaxMacroCharacters)
            refuse(QT_TR_NOOP("macro %1 expands to more than 1 MB of text (a macro that doubles "
                              "itself?): refused before the driver sees it"));
    }
    out.push_back(std::move(p));
}

void Expander::expand(Reader &in, std::vector<Pending> &out, int depth)
{
    while (in.peek()) {
        Pending p = in.take();
        const bool expanding = !m_result.refusal && !m_result.unterminated;
        const int index = expanding && p.token.identifier ? m_defined.value(p.token.text, -1) : -1;
        if (index < 0 || hides(p.hidden, index)) {
            output(out, std::move(p), depth);
            continue;
        }
        if (depth == 0 && p.use < 0) {
            m_uses.push_back({p.token.line, p.token.column, p.token.text});
            m_use = int(m_uses.size()) - 1;
        } else if (depth == 0) {
            m_use = p.use;
        }
        std::optional<std::vector<Pending>> replacement = replace(index, p, in, depth);
        if (replacement)
            in.putBack(std::move(*replacement));
        else
            output(out, std::move(p), depth); // a function-like macro's name without arguments
    }
}

bool Expander::collectArguments(Reader &in, std::vector<std::vector<Pending>> &arguments,
                                std::vector<Pending> &taken)
{
    taken.push_back(in.take()); // "("
    arguments.emplace_back();
    int parentheses = 1;
    while (in.peek() && spend(1)) { // (read in bounded time however often it is retried)
        taken.push_back(in.take());
        const QString &x = taken.back().token.text;
        if (x == QLatin1String("("))
            ++parentheses;
        else if (x == QLatin1String(")") && --parentheses == 0)
            return true;
        else if (x == QLatin1String(",") && parentheses == 1) {
            arguments.emplace_back();
            continue;
        }
        arguments.back().push_back(taken.back());
    }
    return false;
}

std::optional<std::vector<Pending>> Expander::replace(int index, const Pending &use, Reader &in,
                                                      int depth)
{
    const Macro &macro = m_macros[std::size_t(index)];
    std::vector<std::vector<Pending>> arguments;
    if (macro.functionLike) {
        const Pending *open = in.peek();
        if (!open || open->token.text != QLatin1String("("))
            return std::nullopt;
        std::vector<Pending> taken;
        const bool closed = collectArguments(in, arguments, taken);
        if (closed && macro.parameters.isEmpty() && arguments.size() == 1 && arguments[0].empty())
            arguments.clear(); // F()
        if (!closed || int(arguments.size()) != macro.parameters.size()) {
            // The driver says what is wrong; past an argument list that never ends, the
            // rest is left as written (each retry would read to the end again).
            if (!closed && depth == 0)
                m_result.unterminated = true;
            in.putBack(std::move(taken));
            return std::nullopt;
        }
    }
    const int hidden = hideAlso(use.hidden, index);
    const bool conditional = use.token.conditional || macro.conditional;
    std::vector<std::optional<std::vector<Pending>>> expanded(arguments.size());
    std::vector<Pending> out;
    bool paste = false;
    // Each token made belongs to the use being expanded at the top (its place, its name).
    auto add = [&](Pending &&p, bool first) {
        p.use = m_use;
        p.token.conditional = conditional;
        if (first && paste && !out.empty()) {
            GlslToken &left = out.back().token;
            left.text += p.token.text;
            left.identifier = isIdentifier(left.text);
        } else {
            out.push_back(std::move(p));
        }
    };
    for (std::size_t k = 0; k < macro.body.size(); ++k) {
        const GlslToken &b = macro.body[k];
        if (b.text == QLatin1String("##") && k > 0 && k + 1 < macro.body.size()) {
            paste = true;
            continue;
        }
        const int parameter = b.identifier ? int(macro.parameters.indexOf(b.text)) : -1;
        if (parameter < 0) {
            if (!spend(1))
                return std::vector<Pending>{};
            add({b, hidden, -1}, true);
            paste = false;
            continue;
        }
        const std::size_t a = std::size_t(parameter);
        // Beside ## an argument goes in as written; elsewhere macro-expanded first.
        const bool asWritten =
            paste || (k + 1 < macro.body.size() && macro.body[k + 1].text == QLatin1String("##"));
        if (!asWritten && !expanded[a]) {
            if (depth + 1 > kMaxMacroNesting) {
                refuse(QT_TR_NOOP("macro %1 calls macros inside macro arguments more than %2 "
                                  "deep: refused before the driver sees it"),
                       kMaxMacroNesting);
                return std::vector<Pending>{};
            }
            Reader argument(arguments[a]);
            expanded[a].emplace();
            expand(argument, *expanded[a], depth + 1);
        }
        const std::vector<Pending> &piece = asWritten ? arguments[a] : *expanded[a];
        if (!spend(static_cast<long long>(piece.size())))
            return std::vector<Pending>{};
        int from = -2, to = -1; // neighbours mostly share their node: one lookup for them
        for (std::size_t j = 0; j < piece.size(); ++j) {
            if (piece[j].hidden != from) {
                from = piece[j].hidden;
                to = hideAlso(from, index);
            }
            add({piece[j].token, to, -1}, j == 0);
        }
        paste = false;
    }
    return out;
}

void Expander::define(const std::vector<Pending> &list, std::size_t begin, std::size_t end)
{
    if (begin >= end || !list[begin].token.identifier)
        return;
    Macro m;
    m.name = list[begin].token.text;
    m.conditional = m_conditionalDepth > 0;
    m_result.macros.insert(m.name);
    std::size_t k = begin + 1;
    if (k < end && list[k].token.text == QLatin1String("(") && !list[k].token.spaceBefore) {
        m.functionLike = true;
        for (++k;; ++k) {
            if (k >= end)
                return; // no ")": the driver says so
            const GlslToken &t = list[k].token;
            if (t.text == QLatin1String(")"))
                break;
            if (t.identifier)
                m.parameters << t.text;
            else if (t.text != QLatin1String(","))
                return;
        }
        ++k;
    }
    for (; k < end; ++k) {
        m.body.push_back(list[k].token);
        m.body.back().directive = -1;
    }
    m_defined.insert(m.name, int(m_macros.size()));
    m_macros.push_back(std::move(m));
}

void Expander::expandExpression(const std::vector<Pending> &list, std::size_t begin,
                                std::size_t end)
{
    std::vector<Pending> expression;
    for (std::size_t k = begin; k < end; ++k) {
        if (list[k].token.text ==
            QLatin1String("defined")) { // `defined X`, `defined(X)`: X is not expanded
            std::size_t j = k + 1;
            const bool parenthesised = j < end && list[j].token.text == QLatin1String("(");
            j += parenthesised ? 2 : 1;
            if (parenthesised && j < end && list[j].token.text == QLatin1String(")"))
                ++j;
            k = j - 1;
            continue;
        }
        expression.push_back(list[k]);
        expression.back().token.directive = -1;
    }
    Reader reader(expression);
    std::vector<Pending> discarded; // only its size matters: the driver expands it too
    expand(reader, discarded, 0);
}

void Expander::directive(const std::vector<Pending> &list, std::size_t begin, std::size_t end)
{
    if (end - begin < 2)
        return;
    const QString &word = list[begin + 1].token.text;
    if (word == "define")
        define(list, begin + 2, end);
    else if (word == "undef" && end - begin > 2)
        m_defined.remove(list[begin + 2].token.text);
    else if (word == "ifdef" || word == "ifndef")
        ++m_conditionalDepth;
    else if (word == "if") {
        ++m_conditionalDepth;
        expandExpression(list, begin + 2, end);
    } else if (word == "elif" || word == "line")
        expandExpression(list, begin + 2, end);
    else if (word == "endif")
        m_conditionalDepth = std::max(0, m_conditionalDepth - 1);
}

MacroExpansion Expander::run(const QString &source)
{
    std::vector<Pending> list;
    for (GlslToken &t : lexGlsl(source))
        list.push_back({std::move(t), -1});
    Reader top(list);
    std::vector<Pending> out;
    for (std::size_t position = 0; position < list.size();) {
        const int d = list[position].token.directive;
        std::size_t end = position;
        if (d >= 0) {
            while (end < list.size() && list[end].token.directive == d)
                ++end;
            directive(list, position, end);
            position = end;
            continue;
        }
        for (; end < list.size() && list[end].token.directive < 0; ++end)
            list[end].token.conditional = m_conditionalDepth > 0;
        top.setPosition(position);
        expand(top, out, 0);
        position = top.position();
    }
    m_result.tokens.reserve(out.size());
    for (Pending &p : out)
        m_result.tokens.push_back(std::move(p.token));
    return std::move(m_result);
}

} // namespace

QString MacroExpansion::text() const
{
    QString s;
    int line = 1;
    bool lineStart = true;
    for (const GlslToken &t : tokens) {
        for (; line < t.line; ++line) {
            s += '\n';
            lineStart = true;
        }
        if (!lineStart)
            s += ' ';
        s += t.text;
        lineStart = false;
    }
    return s;
}

MacroExpansion expandMacros(const QString &source, ShaderStage stage)
{
    return Expander(stage).run(source);
}

std::optional<Diagnostic> macroExpansionRefusal(const QString &source, ShaderStage stage)
{
    return expandMacros(source, stage).refusal;
}

} // namespace lb
