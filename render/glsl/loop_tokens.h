#pragma once
// The loop reader's view of the code (loops.cpp): the tokens after the source's macros are
// expanded (a loop behind `#define FOREVER for (;;)` is read like one written out), each on the
// line where the user wrote it or used the macro that made it, and the questions the reader
// asks of a stretch [begin, end) of them.

#include "glsl_lexer.h"

#include <QSet>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

namespace lb::looptokens {

using Token = GlslToken;

// The index of the bracket closing the one at `open`, or the end.
std::size_t closing(const std::vector<Token> &t, std::size_t open);

// The statement starting at `i`: a block, or up to its ';' outside brackets. [begin, end).
std::pair<std::size_t, std::size_t> statementAt(const std::vector<Token> &t, std::size_t i);

// Functions the file defines: a name and its parameters, then a body, outside any block.
QSet<QString> definedFunctions(const std::vector<Token> &t);

// What a stretch of tokens writes to: assigned, incremented or decremented names.
void collectChanged(const std::vector<Token> &t, std::size_t begin, std::size_t end,
                    QSet<QString> &changed);

bool exits(const std::vector<Token> &t, std::size_t begin, std::size_t end);

bool callsAny(const std::vector<Token> &t, std::size_t begin, std::size_t end,
              const QSet<QString> &functions);

bool alwaysTrue(const std::vector<Token> &t, std::size_t begin, std::size_t end);

// The names a condition reads (not function names, not members after a dot).
QStringList namesRead(const std::vector<Token> &t, std::size_t begin, std::size_t end);

// The semicolons that split a for's parentheses [open, close] into its three parts.
std::vector<std::size_t> forSemicolons(const std::vector<Token> &t, std::size_t open,
                                       std::size_t close);

// How many times `for (int i = A; i < B; i++)` runs, read from its three parts when they are
// that simple: a literal start and bound, a comparison of the counter with the bound (<, <=,
// !=, >, >=), and a literal step (++, --, += C, -= C). nullopt for anything else. A counter
// that moves away from its bound (`i >= 0; i++`) runs until it wraps around (GLSL's integers
// do: 2^31 steps for an int), and `wraps` says so.
std::optional<double> countedSteps(const std::vector<Token> &t, std::size_t ib, std::size_t ie,
                                   std::size_t cb, std::size_t ce, std::size_t sb, std::size_t se,
                                   bool *wraps = nullptr);

} // namespace lb::looptokens
