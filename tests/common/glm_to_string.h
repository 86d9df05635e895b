#pragma once
// QTest::toString for GLM's vectors and matrices, so that QCOMPARE on them prints both values
// when they differ. Found by argument-dependent lookup, hence namespace glm.

#include <QByteArray>
#include <QTest>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace glm {

namespace lb_test_detail {
template <typename Vector> QByteArray numbers(const Vector &v)
{
    QByteArray text = "(";
    for (length_t i = 0; i < Vector::length(); ++i)
        text += (i ? ", " : "") + QByteArray::number(double(v[i]), 'g', 7);
    return text + ")";
}
} // namespace lb_test_detail

template <length_t N, typename T, qualifier Q> char *toString(const vec<N, T, Q> &v)
{
    return qstrdup(lb_test_detail::numbers(v).constData());
}

// Columns, as GLM stores them: m[0] is the first column.
template <length_t C, length_t R, typename T, qualifier Q> char *toString(const mat<C, R, T, Q> &m)
{
    QByteArray text = "columns ";
    for (length_t c = 0; c < C; ++c)
        text += lb_test_detail::numbers(m[c]);
    return qstrdup(text.constData());
}

} // namespace glm

// The same text as a QByteArray, for QVERIFY2 messages: glmText(v).constData().
template <typename T> QByteArray glmText(const T &value)
{
    char *text = glm::toString(value);
    const QByteArray copy(text);
    delete[] text;
    return copy;
}
