#pragma once
// The tokens the macro expander (macro_expansion.cpp) works on: a token on its way, the uses of
// macros in the source, and the reader that hands them out.

#include "glsl_lexer.h"

#include <QString>

#include <cstddef>
#include <vector>

namespace lb::macro_tokens {

// A token on its way, with the macros that must not expand it again (a node of
// Expander::m_hidden; -1: none: this is how `#define x x+1` ends after one step), and the use
// in the source whose expansion made it (an index of Expander::m_uses; -1: written out). Its
// place and macro name are filled in only when it comes out (copies of a QString cost).
struct Pending
{
    GlslToken token;
    int hidden = -1;
    int use = -1;
};

// Where a macro is used in the source, and its name.
struct Use
{
    int line, column;
    QString macro;
};

// Tokens in order: what an expansion put back first (rescanned together with what follows,
// as C does, so a function-like macro can take its arguments from there), then the list from
// the position on, up to a directive line.
class Reader
{
public:
    explicit Reader(const std::vector<Pending> &list, std::size_t position = 0)
        : m_list(list), m_position(position)
    {
    }
    const Pending *peek() const
    {
        if (!m_back.empty())
            return &m_back.back();
        if (m_position < m_list.size() && m_list[m_position].token.directive < 0)
            return &m_list[m_position];
        return nullptr;
    }
    Pending take()
    {
        if (m_back.empty())
            return m_list[m_position++];
        Pending p = std::move(m_back.back());
        m_back.pop_back();
        return p;
    }
    void putBack(std::vector<Pending> &&tokens) // read next, in their order
    {
        for (auto it = tokens.rbegin(); it != tokens.rend(); ++it)
            m_back.push_back(std::move(*it));
    }
    std::size_t position() const { return m_position; }
    void setPosition(std::size_t position) { m_position = position; }

private:
    const std::vector<Pending> &m_list;
    std::size_t m_position;
    std::vector<Pending> m_back; // the next token last
};

} // namespace lb::macro_tokens
