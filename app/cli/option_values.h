#pragma once
// The parser's readers of one option's value (command_line.cpp and the files beside it): each
// returns the value or throws BadOption with the option's name and what was wrong, which
// parseCommandLine() turns into its one-line message.

#include "lighting_parameters.h"

#include <QString>
#include <QStringList>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace lb::options {

// Thrown inside the parser only; parseCommandLine() turns it into a CommandLineResult.
struct BadOption
{
    QString message;
};

// What the user typed, as a message repeats it: a pasted megabyte or a pasted line break
// stays one readable line.
QString echoed(const QString &text, int max = 80);
[[noreturn]] void fail(const QString &option, const QString &what);
// `count` finite numbers separated by commas (`shape` names them: "X,Y,Z").
std::vector<float> numbers(const QString &option, const QString &text, int count,
                           const char *shape);
void checkRange(const QString &option, float v, float lo, float hi);
glm::vec3 vec3Option(const QString &option, const QString &text, float lo, float hi);
// A row of the lighting model's table (lighting_parameters.h): its numbers, each within the
// row's range, refused as a whole where the row refuses them.
std::vector<float> parameterOption(const LightingParameter &p, const QString &option,
                                   const QString &text);
void checkParameter(const LightingParameter &p, const QString &option, const std::vector<float> &v);
bool onOff(const QString &option, const QString &text);
int integer(const QString &option, const QString &text, int lo, int hi);
QString readShader(const char *option, const QString &path); // the file's text

// One of `names`, as `parse` reads it.
template <typename E>
E word(const QString &option, const QString &text, std::optional<E> (*parse)(const QString &),
       const QStringList &names)
{
    if (const auto v = parse(text))
        return *v;
    fail(option, QString("unknown value '%1' (expected %2)").arg(echoed(text), names.join('|')));
}

} // namespace lb::options
