#pragma once
// Reads the fields of a scene's JSON (scene_json.cpp) into a Scene, keeping the default of each
// field it cannot use and naming it in `ignored`: "object.tessellation (out of range, clamped)",
// "lights[2].frame (unknown value)". The path is the file's own spelling (data, never
// translated); the reason after it is a message, translated in the context lb::SceneJson.

#include "localized_text.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

namespace lb {

class SceneJsonReader
{
    Q_DECLARE_TR_FUNCTIONS(lb::SceneJson)

public:
    explicit SceneJsonReader(QStringList *ignored) : m_ignored(ignored) {}

    // `why`: a message (tr()).
    void ignore(const QString &path, const QString &why);

    // The object under `key`; an absent key gives an empty object, a non-object is ignored.
    QJsonObject object(const QJsonObject &o, const QString &key, const QString &path);

    // Names each key of `o` that `known` (the same object as written) lacks.
    void unknownKeys(const QJsonObject &o, const QJsonObject &known, const QString &path);

    void numbers(const QJsonObject &o, const QString &key, const QString &path, float *v, int n,
                 float lo, float hi);

    template <typename T>
    void number(const QJsonObject &o, const QString &key, const QString &path, T &v, T lo, T hi)
    {
        const QJsonValue j = o.value(key);
        if (j.isUndefined())
            return;
        if (!j.isDouble() || !std::isfinite(j.toDouble())) {
            ignore(join(path, key), tr("not a number"));
            return;
        }
        const double d = j.toDouble();
        const double c = std::clamp(d, double(lo), double(hi));
        v = T(c);
        const bool fraction = std::is_integral_v<T> && double(v) != c;
        if (c != d || fraction)
            ignore(join(path, key),
                   fraction ? tr("not a whole number") : tr("out of range, clamped"));
    }

    void boolean(const QJsonObject &o, const QString &key, const QString &path, bool &v);

    template <typename E>
    void word(const QJsonObject &o, const QString &key, const QString &path,
              std::optional<E> (*parse)(const QString &), E &v)
    {
        const QJsonValue j = o.value(key);
        if (j.isUndefined())
            return;
        if (const auto parsed = parse(j.toString()))
            v = *parsed;
        else
            ignore(join(path, key), tr("unknown value"));
    }

    void text(const QJsonObject &o, const QString &key, const QString &path, QString &v);
    // An object's or a program's name: a string or {language: string}, each at most
    // kMaxNameCharacters (readLocalizedText); an absent key leaves `v`.
    void name(const QJsonObject &o, const QString &key, const QString &path, LocalizedText &v);
    // As a name is written: "" when there is none, else localizedTextJson().
    static QJsonValue nameJson(const LocalizedText &name);

    static QString join(const QString &path, const QString &key)
    {
        return path.isEmpty() ? key : path + "." + key;
    }

private:
    QStringList *m_ignored;
};

} // namespace lb
