#include "glsl_lexer.h"

#include <QStringList>
#include <QStringView>

namespace lb {

bool startsIdentifier(QChar c)
{
    return c.isLetter() || c == '_';
}

std::vector<GlslToken> lexGlsl(const QString &s)
{
    // Longest first, so that "<<=" is not read as "<<" and "=".
    static const QStringList operators{
        "<<=", ">>=", "##", "++", "--", "+=", "-=", "*=", "/=", "%=", "&=",
        "|=",  "^=",  "==", "!=", "<=", ">=", "&&", "||", "^^", "<<", ">>"};
    std::vector<GlslToken> tokens;
    const QStringView view(s);
    int line = 1, lineStart = 0;
    bool lineHasToken = false; // a token before on this line: a `#` now is no directive
    bool inDirective = false;
    int directives = 0;
    bool space = true;
    const int n = int(s.size());
    for (int i = 0; i < n;) {
        const QChar c = s[i];
        if (c == '\\' && i + 1 < n &&
            (s[i + 1] == '\n' || (s[i + 1] == '\r' && i + 2 < n && s[i + 2] == '\n'))) {
            // A continuation: the logical line (a directive's too) goes on.
            i += s[i + 1] == '\r' ? 3 : 2;
            ++line;
            lineStart = i;
            space = true;
            continue;
        }
        if (c == '\n') {
            ++line;
            lineStart = ++i;
            lineHasToken = false;
            inDirective = false;
            space = true;
            continue;
        }
        if (c.isSpace()) {
            ++i;
            space = true;
            continue;
        }
        if (c == '/' && i + 1 < n && s[i + 1] == '/') { // to the end of the line
            while (i < n && s[i] != '\n')
                ++i;
            space = true;
            continue;
        }
        if (c == '/' && i + 1 < n && s[i + 1] == '*') {
            // One space, as for the preprocessor: a directive goes on past its newlines.
            i += 2;
            while (i < n && !(s[i] == '*' && i + 1 < n && s[i + 1] == '/')) {
                if (s[i] == '\n') {
                    ++line;
                    lineStart = i + 1;
                }
                ++i;
            }
            i += 2;
            space = true;
            continue;
        }
        GlslToken t;
        t.line = line;
        t.column = i - lineStart + 1;
        t.spaceBefore = space;
        space = false;
        if (c == '#' && !lineHasToken) {
            inDirective = true;
            ++directives;
        }
        lineHasToken = true;
        t.directive = inDirective ? directives - 1 : -1;
        if (startsIdentifier(c)) {
            const int start = i;
            while (i < n && (s[i].isLetterOrNumber() || s[i] == '_'))
                ++i;
            t.text = s.mid(start, i - start);
            t.identifier = true;
        } else if (c.isDigit() || (c == '.' && i + 1 < n && s[i + 1].isDigit())) {
            const int start = i;
            while (i < n &&
                   (s[i].isLetterOrNumber() || s[i] == '.' ||
                    ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
                ++i;
            t.text = s.mid(start, i - start);
        } else {
            t.text = c;
            for (const QString &op : operators)
                if (view.mid(i, op.size()) == op) {
                    t.text = op;
                    break;
                }
            i += int(t.text.size());
        }
        tokens.push_back(std::move(t));
    }
    return tokens;
}

} // namespace lb
