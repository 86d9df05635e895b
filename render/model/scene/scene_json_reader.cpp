#include "scene_json_reader.h"

#include "message_text.h"
#include "scene.h"

namespace lb {

void SceneJsonReader::ignore(const QString &path, const QString &why)
{
    if (m_ignored)
        //: a field of a scene file as the file spells it (%1, "lights[2].frame", never
        //: translated) and why it was not used (%2)
        // The name is the file's: escaped, so that an escape sequence or a line break in a
        // field's name reaches no terminal (values were escaped already; names were not).
        m_ignored->append(tr("%1 (%2)").arg(escapedName(elidedForMessage(path)), why));
}

QJsonObject SceneJsonReader::object(const QJsonObject &o, const QString &key, const QString &path)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined())
        return {};
    if (!v.isObject())
        ignore(path, tr("not an object"));
    return v.toObject();
}

void SceneJsonReader::unknownKeys(const QJsonObject &o, const QJsonObject &known,
                                  const QString &path)
{
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!known.contains(it.key()))
            ignore(join(path, it.key()), tr("unknown field"));
}

void SceneJsonReader::numbers(const QJsonObject &o, const QString &key, const QString &path,
                              float *v, int n, float lo, float hi)
{
    const QJsonValue j = o.value(key);
    if (j.isUndefined())
        return;
    const QJsonArray a = j.toArray();
    bool ok = j.isArray() && a.size() == n;
    for (int i = 0; ok && i < n; ++i)
        ok = a[i].isDouble() && std::isfinite(a[i].toDouble());
    if (!ok) {
        ignore(join(path, key), n == 1 ? tr("not a number") : tr("not an array of numbers"));
        return;
    }
    bool clamped = false;
    for (int i = 0; i < n; ++i) {
        const double d = a[i].toDouble();
        const double c = std::clamp(d, double(lo), double(hi));
        v[i] = float(c);
        clamped = clamped || c != d;
    }
    if (clamped)
        ignore(join(path, key), tr("out of range, clamped"));
}

void SceneJsonReader::boolean(const QJsonObject &o, const QString &key, const QString &path,
                              bool &v)
{
    const QJsonValue j = o.value(key);
    if (j.isBool())
        v = j.toBool();
    else if (!j.isUndefined())
        ignore(join(path, key), tr("not true or false"));
}

void SceneJsonReader::text(const QJsonObject &o, const QString &key, const QString &path,
                           QString &v)
{
    const QJsonValue j = o.value(key);
    if (j.isString())
        v = j.toString();
    else if (!j.isUndefined())
        ignore(join(path, key), tr("not a string"));
}

void SceneJsonReader::name(const QJsonObject &o, const QString &key, const QString &path,
                           LocalizedText &v)
{
    if (!o.contains(key))
        return;
    v = readLocalizedText(o.value(key), join(path, key), limits::kMaxNameCharacters,
                          [this](const QString &where, const QString &why) { ignore(where, why); });
}

QJsonValue SceneJsonReader::nameJson(const LocalizedText &name)
{
    return name.isEmpty() ? QJsonValue(QString()) : localizedTextJson(name);
}

} // namespace lb
