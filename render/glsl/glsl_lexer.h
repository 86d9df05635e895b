#pragma once
// GLSL source cut into preprocessing tokens: words, numbers and operators, each with the place
// the user wrote it; comments and line continuations are gone. The tokens of a directive line
// (`#` first on its line) are kept, marked with the directive they belong to, for the macro
// expansion (macro_expansion.h); the loop reader (loops.h) reads what that expansion gives.

#include <QString>

#include <vector>

namespace lb {

struct GlslToken
{
    QString text;
    int line = 1;   // 1-based, in the user's source; for a macro's expansion, where it is used
    int column = 1; // 1-based, likewise
    bool identifier = false;
    bool spaceBefore = false; // whitespace or a comment before it: `#define F(x)` vs `F (x)`
    bool conditional = false; // inside #if/#ifdef/#ifndef: maybe not compiled at all
    int directive = -1;       // which directive line (0, 1, ...) it belongs to; -1 in code
    QString macro; // the macro used in the source whose expansion made it; empty when written
};

std::vector<GlslToken> lexGlsl(const QString &source);

bool startsIdentifier(QChar c);

} // namespace lb
