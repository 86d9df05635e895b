#include "option_values.h"

#include "command_line.h"
#include "message_text.h"
#include "scene.h"
#include "shader_document.h"

#include <cmath>

namespace lb::options {

// What the user typed, as a message repeats it: a pasted megabyte or a pasted line break
// stays one readable line.
QString echoed(const QString &text, int max)
{
    return echoedValue(text, max);
}

void fail(const QString &option, const QString &what)
{
    throw BadOption{QString("--%1: %2").arg(option, what)};
}

std::vector<float> numbers(const QString &option, const QString &text, int count, const char *shape)
{
    const QStringList parts = text.split(',');
    if (parts.size() != count)
        fail(option, QString("expected %1, got '%2'").arg(shape, echoed(text)));
    std::vector<float> values;
    for (const QString &part : parts) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v))
            fail(option,
                 QString("'%1' is not a finite number (expected %2)").arg(echoed(part), shape));
        values.push_back(float(v));
    }
    return values;
}

void checkRange(const QString &option, float v, float lo, float hi)
{
    if (v < lo || v > hi)
        fail(option, QString("%1 is outside %2 to %3").arg(v).arg(lo).arg(hi));
}

glm::vec3 vec3Option(const QString &option, const QString &text, float lo, float hi)
{
    const auto v = numbers(option, text, 3, "X,Y,Z");
    for (float x : v)
        checkRange(option, x, lo, hi);
    return glm::vec3(v[0], v[1], v[2]);
}

std::vector<float> parameterOption(const LightingParameter &p, const QString &option,
                                   const QString &text)
{
    const std::vector<float> v =
        numbers(option, text, p.count, p.count == 1 ? "a number" : p.metavar);
    checkParameter(p, option, v);
    return v;
}

void checkParameter(const LightingParameter &p, const QString &option, const std::vector<float> &v)
{
    for (float x : v)
        checkRange(option, x, p.lo, p.hi);
    const QString refused = p.refusalInEnglish(v.data());
    if (!refused.isEmpty())
        fail(option, refused);
}

bool onOff(const QString &option, const QString &text)
{
    const QStringList names = onOffNames(); // "on", "off"
    if (text == names[0])
        return true;
    if (text == names[1])
        return false;
    fail(option, QString("expected on or off, got '%1'").arg(echoed(text)));
}

int integer(const QString &option, const QString &text, int lo, int hi)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok)
        fail(option, QString("'%1' is not a whole number").arg(echoed(text)));
    if (v < lo || v > hi)
        fail(option, QString("%1 is outside %2 to %3").arg(v).arg(lo).arg(hi));
    return v;
}

QString readShader(const char *option, const QString &path)
{
    const ShaderFileRead read = readShaderFile(path);
    if (!read.ok())
        fail(option, "cannot read " + read.error);
    return read.text;
}

} // namespace lb::options
