#include "scene.h"

#include <QJsonArray>

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace lb {

namespace {

template <typename E, std::size_t N> using NameTable = std::array<std::pair<E, const char *>, N>;

constexpr NameTable<LightFrame, 3> kFrames{
    {{LightFrame::Camera, "camera"}, {LightFrame::World, "world"}, {LightFrame::Object, "object"}}};
constexpr NameTable<Shading, 2> kShadings{
    {{Shading::Gouraud, "gouraud"}, {Shading::Phong, "phong"}}};
constexpr NameTable<SpecularModel, 2> kSpeculars{
    {{SpecularModel::Phong, "phong"}, {SpecularModel::Blinn, "blinn"}}};
constexpr NameTable<Projection, 2> kProjections{
    {{Projection::Perspective, "perspective"}, {Projection::Orthographic, "orthographic"}}};
constexpr NameTable<Shape, 4> kShapes{{{Shape::Cube, "cube"},
                                       {Shape::Sphere, "sphere"},
                                       {Shape::Torus, "torus"},
                                       {Shape::Plane, "plane"}}};
constexpr NameTable<NormalMode, 3> kNormalModes{
    {{NormalMode::File, "file"}, {NormalMode::Smooth, "smooth"}, {NormalMode::Flat, "flat"}}};

template <typename E, std::size_t N> QString nameOf(const NameTable<E, N> &table, E value)
{
    for (const auto &[v, name] : table)
        if (v == value)
            return QString::fromLatin1(name);
    return {};
}

template <typename E, std::size_t N>
std::optional<E> valueOf(const NameTable<E, N> &table, const QString &name)
{
    for (const auto &[v, n] : table)
        if (name == QLatin1String(n))
            return v;
    return std::nullopt;
}

template <typename E, std::size_t N> QStringList namesOf(const NameTable<E, N> &table)
{
    QStringList names;
    for (const auto &entry : table)
        names << QString::fromLatin1(entry.second);
    return names;
}

QJsonArray toArray(const float *v, int n)
{
    QJsonArray a;
    for (int i = 0; i < n; ++i)
        a.append(double(v[i]));
    return a;
}

// Reads n numbers into v when the field is an array of n finite numbers; otherwise keeps v
// and returns false.
bool readArray(const QJsonObject &o, const QString &key, float *v, int n)
{
    const QJsonArray a = o.value(key).toArray();
    if (a.size() != n)
        return false;
    for (int i = 0; i < n; ++i)
        if (!a[i].isDouble() || !std::isfinite(a[i].toDouble()))
            return false;
    for (int i = 0; i < n; ++i)
        v[i] = float(a[i].toDouble());
    return true;
}

template <typename T> void readNumber(const QJsonObject &o, const char *key, T &v)
{
    const QJsonValue j = o.value(QLatin1String(key));
    if (j.isDouble() && std::isfinite(j.toDouble()))
        v = T(j.toDouble());
}

void readBool(const QJsonObject &o, const char *key, bool &v)
{
    const QJsonValue j = o.value(QLatin1String(key));
    if (j.isBool())
        v = j.toBool();
}

template <typename E, std::size_t N>
void readEnum(const QJsonObject &o, const char *key, const NameTable<E, N> &table, E &v)
{
    if (auto parsed = valueOf(table, o.value(QLatin1String(key)).toString()))
        v = *parsed;
}

} // namespace

QString toName(LightFrame v)
{
    return nameOf(kFrames, v);
}
QString toName(Shading v)
{
    return nameOf(kShadings, v);
}
QString toName(SpecularModel v)
{
    return nameOf(kSpeculars, v);
}
QString toName(Projection v)
{
    return nameOf(kProjections, v);
}
QString toName(Shape v)
{
    return nameOf(kShapes, v);
}
QString toName(NormalMode v)
{
    return nameOf(kNormalModes, v);
}
std::optional<LightFrame> parseLightFrame(const QString &s)
{
    return valueOf(kFrames, s);
}
std::optional<Shading> parseShading(const QString &s)
{
    return valueOf(kShadings, s);
}
std::optional<SpecularModel> parseSpecularModel(const QString &s)
{
    return valueOf(kSpeculars, s);
}
std::optional<Projection> parseProjection(const QString &s)
{
    return valueOf(kProjections, s);
}
std::optional<Shape> parseShape(const QString &s)
{
    return valueOf(kShapes, s);
}
std::optional<NormalMode> parseNormalMode(const QString &s)
{
    return valueOf(kNormalModes, s);
}
QStringList lightFrameNames()
{
    return namesOf(kFrames);
}
QStringList shadingNames()
{
    return namesOf(kShadings);
}
QStringList specularModelNames()
{
    return namesOf(kSpeculars);
}
QStringList projectionNames()
{
    return namesOf(kProjections);
}
QStringList shapeNames()
{
    return namesOf(kShapes);
}
QStringList normalModeNames()
{
    return namesOf(kNormalModes);
}

QJsonObject Scene::toJson() const
{
    QJsonObject l;
    l["position"] = toArray(&light.position.x, 4);
    l["frame"] = toName(light.frame);
    l["ia"] = toArray(&light.colors.ia.x, 3);
    l["id"] = toArray(&light.colors.id.x, 3);
    l["is"] = toArray(&light.colors.is.x, 3);

    QJsonObject m;
    m["ka"] = toArray(&material.ka.x, 3);
    m["kd"] = toArray(&material.kd.x, 3);
    m["ks"] = toArray(&material.ks.x, 3);
    m["shininess"] = double(material.shininess);

    QJsonObject s;
    s["shading"] = toName(shading.shading);
    s["specular"] = toName(shading.specular);
    s["projection"] = toName(shading.projection);
    s["lighting"] = shading.lighting;
    s["vertexColors"] = shading.vertexColors;
    s["texture"] = shading.texture;

    QJsonObject ob;
    ob["shape"] = toName(object.shape);
    ob["tessellation"] = object.tessellation;
    ob["rotation"] = toArray(&object.rotationDegrees.x, 3);
    ob["scale"] = toArray(&object.scale.x, 3);
    ob["autoRotate"] = object.autoRotate;
    ob["mesh"] = object.meshPath;
    ob["normals"] = toName(object.normals);
    ob["creaseAngle"] = double(object.creaseDegrees);
    ob["showNormals"] = object.showNormals;
    ob["adoptFileMaterial"] = object.adoptFileMaterial;

    QJsonObject c;
    c["target"] = toArray(&camera.target.x, 3);
    c["distance"] = double(camera.distance);
    c["yaw"] = double(camera.yawDegrees);
    c["pitch"] = double(camera.pitchDegrees);

    QJsonObject root;
    root["version"] = 1;
    root["light"] = l;
    root["material"] = m;
    root["shading"] = s;
    root["object"] = ob;
    root["camera"] = c;
    root["showLight"] = showLight;
    QJsonObject values;
    for (const auto &[name, v] : shaderValues)
        values[name] = toArray(v.data(), int(v.size()));
    root["shaderValues"] = values;
    return root;
}

Scene Scene::fromJson(const QJsonObject &json)
{
    Scene sc;
    const QJsonObject l = json.value("light").toObject();
    readArray(l, "position", &sc.light.position.x, 4);
    if (sc.light.position.w != 0.0f && sc.light.position.w != 1.0f)
        sc.light.position.w = 1.0f;
    readEnum(l, "frame", kFrames, sc.light.frame);
    readArray(l, "ia", &sc.light.colors.ia.x, 3);
    readArray(l, "id", &sc.light.colors.id.x, 3);
    readArray(l, "is", &sc.light.colors.is.x, 3);

    const QJsonObject m = json.value("material").toObject();
    readArray(m, "ka", &sc.material.ka.x, 3);
    readArray(m, "kd", &sc.material.kd.x, 3);
    readArray(m, "ks", &sc.material.ks.x, 3);
    readNumber(m, "shininess", sc.material.shininess);
    sc.material.shininess =
        std::clamp(sc.material.shininess, limits::kMinShininess, limits::kMaxShininess);

    const QJsonObject s = json.value("shading").toObject();
    readEnum(s, "shading", kShadings, sc.shading.shading);
    readEnum(s, "specular", kSpeculars, sc.shading.specular);
    readEnum(s, "projection", kProjections, sc.shading.projection);
    readBool(s, "lighting", sc.shading.lighting);
    readBool(s, "vertexColors", sc.shading.vertexColors);
    readBool(s, "texture", sc.shading.texture);

    const QJsonObject ob = json.value("object").toObject();
    readEnum(ob, "shape", kShapes, sc.object.shape);
    readNumber(ob, "tessellation", sc.object.tessellation);
    sc.object.tessellation =
        std::clamp(sc.object.tessellation, limits::kMinTessellation, limits::kMaxTessellation);
    readArray(ob, "rotation", &sc.object.rotationDegrees.x, 3);
    readArray(ob, "scale", &sc.object.scale.x, 3);
    sc.object.scale = glm::clamp(sc.object.scale, limits::kMinScale, limits::kMaxScale);
    readBool(ob, "autoRotate", sc.object.autoRotate);
    if (ob.value("mesh").isString())
        sc.object.meshPath = ob.value("mesh").toString();
    readEnum(ob, "normals", kNormalModes, sc.object.normals);
    readNumber(ob, "creaseAngle", sc.object.creaseDegrees);
    sc.object.creaseDegrees = std::clamp(sc.object.creaseDegrees, 0.0f, limits::kMaxCreaseDegrees);
    readBool(ob, "showNormals", sc.object.showNormals);
    readBool(ob, "adoptFileMaterial", sc.object.adoptFileMaterial);

    const QJsonObject c = json.value("camera").toObject();
    readArray(c, "target", &sc.camera.target.x, 3);
    readNumber(c, "distance", sc.camera.distance);
    readNumber(c, "yaw", sc.camera.yawDegrees);
    readNumber(c, "pitch", sc.camera.pitchDegrees);
    // Re-apply the camera's own limits to whatever the file held.
    sc.camera.zoom(0.0f);
    sc.camera.orbit(0.0f, 0.0f);

    readBool(json, "showLight", sc.showLight);
    const QJsonObject values = json.value("shaderValues").toObject();
    for (auto it = values.begin(); it != values.end(); ++it) {
        const int n = int(it.value().toArray().size());
        std::vector<float> v(std::size_t(std::clamp(n, 1, 4)), 0.0f);
        if (n >= 1 && n <= 4 && readArray(values, it.key(), v.data(), n))
            sc.shaderValues[it.key()] = v;
    }
    return sc;
}

bool operator==(const Scene &a, const Scene &b)
{
    // The JSON holds every field, so comparing it keeps this in step with the model.
    return a.toJson() == b.toJson();
}

} // namespace lb
