#pragma once
// GLSL highlighting: QScintilla's C++ lexer with GLSL's keywords, types and built-ins
// (GLSL ES 1.00 through 4.x, so pasted WebGL code and core code both read right).

#include <Qsci/qscilexercpp.h>

namespace lb {

class GlslLexer : public QsciLexerCPP
{
    Q_OBJECT
public:
    explicit GlslLexer(QObject *parent = nullptr);
    const char *language() const override { return "GLSL"; }
    const char *keywords(int set) const override;

    // Every keyword and built-in, for completion.
    static const QStringList &completionWords();
};

} // namespace lb
