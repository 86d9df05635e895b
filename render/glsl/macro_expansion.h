#pragma once
// The macros a GLSL source defines, expanded as the driver's preprocessor expands them
// (#define and #undef, object-like and function-like, arguments expanded before they are put
// in, `##`, a macro not expanded again inside its own expansion), so that what the text reads
// is what the driver compiles: a `#define FOREVER for (;;)` is a loop like one written out.
//
// With a bound: Mesa's preprocessor expands without one, and a 946-byte source whose macros
// double 40 times grew it to 24 GB (issue 29). Past a million tokens made, or 1 MB of text out
// of macros, for the whole file, the expansion stops and the source is refused, on the line
// where the macro is used, before the driver sees it.
//
// #if, #ifdef and #ifndef are not evaluated: every branch is read (definitions in it too), and
// what lies in one is marked `conditional` (the loop reader leaves it alone). The
// expressions of #if and #elif are expanded as well (the driver expands them), for the bound.

#include "diagnostics.h"
#include "glsl_lexer.h"

#include <QSet>
#include <QString>

#include <optional>
#include <vector>

namespace lb {

constexpr long long kMaxMacroTokens = 1000000;         // tokens made by expansions, whole file
constexpr long long kMaxMacroCharacters = 1024 * 1024; // text out of macros, whole file
// Macro calls inside macro arguments, or macros expanding one into the next, so deep.
constexpr int kMaxMacroNesting = 200;

struct MacroExpansion
{
    // The code after expansion, without directives. A token a macro made has the line and
    // column where that macro is used in the source, and its name in `macro`.
    std::vector<GlslToken> tokens;
    // Every name the source #defines: one still in `tokens` was not expanded (inside its own
    // expansion, a function-like macro without arguments, or left after a refusal).
    QSet<QString> macros;
    // Set when the bound was passed: the source must not reach the driver.
    std::optional<Diagnostic> refusal;
    // An argument list that never ends (the driver will say so): expansion stopped there.
    bool unterminated = false;

    // The expanded code as text, source line N on line N (what a macro makes on the line of
    // its use): a place in the text is a place in the user's source, up to the column.
    QString text() const;
};

MacroExpansion expandMacros(const QString &source, ShaderStage stage = ShaderStage::Fragment);

// Only the refusal (an error diagnostic), for the checks before the driver.
std::optional<Diagnostic> macroExpansionRefusal(const QString &source, ShaderStage stage);

} // namespace lb
