// Scene <-> JSON. Writing gives every field; reading takes what it can use and names the rest.

#include "scene.h"
#include "scene_json_reader.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

namespace lb {

namespace {

QJsonArray toArray(const float *v, int n)
{
    QJsonArray a;
    for (int i = 0; i < n; ++i)
        a.append(double(v[i]));
    return a;
}

// A row's key: "cutoff" in the object under "spot" for "spot.cutoff".
struct ParameterKey
{
    QString object; // empty: the owner's own object
    QString key;
};

ParameterKey keyOf(const LightingParameter &p)
{
    const QString key = QString::fromLatin1(p.key);
    const int dot = int(key.indexOf('.'));
    if (dot < 0)
        return {{}, key};
    return {key.left(dot), key.mid(dot + 1)};
}

// The numbers of the owner's rows (lighting_parameters.h): one number as a number, more as
// an array.
template <typename Owner> void writeParameters(QJsonObject &json, ParameterOwner of, const Owner &o)
{
    for (const LightingParameter *p : lightingParameters(of)) {
        const ParameterKey k = keyOf(*p);
        const QJsonValue v = p->count == 1 ? QJsonValue(double(*p->numbers(o)))
                                           : QJsonValue(toArray(p->numbers(o), p->count));
        if (k.object.isEmpty()) {
            json[k.key] = v;
        } else {
            QJsonObject inner = json[k.object].toObject();
            inner[k.key] = v;
            json[k.object] = inner;
        }
    }
}

QJsonObject lightJson(const Light &light)
{
    QJsonObject l;
    l["enabled"] = light.enabled;
    l["frame"] = toName(light.frame);
    l["object"] = light.object;
    writeParameters(l, ParameterOwner::Light, light);
    return l;
}

QJsonObject materialJson(const Material &material)
{
    QJsonObject m;
    writeParameters(m, ParameterOwner::Material, material);
    return m;
}

// Version 2's "object" held all of this but the name, visibility, translation, material and
// texture switch (those were "material" and "shading.texture").
QJsonObject objectJson(const ObjectSettings &object)
{
    QJsonObject ob;
    ob["name"] = SceneJsonReader::nameJson(object.name);
    ob["visible"] = object.visible;
    ob["shape"] = toName(object.shape);
    ob["tessellation"] = object.tessellation;
    ob["rotation"] = toArray(&object.rotationDegrees.x, 3);
    ob["scale"] = toArray(&object.scale.x, 3);
    ob["translation"] = toArray(&object.translation.x, 3);
    ob["autoRotate"] = object.autoRotate;
    ob["mesh"] = object.meshPath;
    ob["normals"] = toName(object.normals);
    ob["faces"] = toName(object.faces);
    ob["creaseAngle"] = double(object.creaseDegrees);
    ob["showNormals"] = object.showNormals;
    ob["cullBackFaces"] = object.cullBackFaces;
    ob["adoptFileMaterial"] = object.adoptFileMaterial;
    ob["material"] = materialJson(object.material);
    ob["texture"] = object.texture;
    ob["textureFile"] = object.textureFile;
    ob["textureWrap"] = toName(object.sampling.wrap);
    ob["textureFilter"] = toName(object.sampling.filter);
    ob["textureMipmaps"] = object.sampling.mipmaps;
    return ob;
}

QJsonObject termsJson(const TermSwitches &terms)
{
    QJsonObject t;
    t["ambient"] = terms.ambient;
    t["diffuse"] = terms.diffuse;
    t["specular"] = terms.specular;
    return t;
}

// The translation context of the reasons named in `ignored` (scene_json_reader.h).
struct SceneJsonMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::SceneJson)
};

// Each row of the owner's (lighting_parameters.h) within its range; numbers the row refuses as
// a whole keep what they were, named with the row's reason. The objects a row lies in ("spot")
// are read once, their unknown keys named.
template <typename Owner>
void readParameters(SceneJsonReader &r, const QJsonObject &json, const QString &path,
                    ParameterOwner of, Owner &o, const QJsonObject &known)
{
    std::map<QString, QJsonObject> inner;
    for (const LightingParameter *p : lightingParameters(of)) {
        const ParameterKey k = keyOf(*p);
        QString where = path;
        const QJsonObject *in = &json;
        if (!k.object.isEmpty()) {
            where = SceneJsonReader::join(path, k.object);
            if (!inner.count(k.object)) {
                inner[k.object] = r.object(json, k.object, where);
                r.unknownKeys(inner[k.object], known[k.object].toObject(), where);
            }
            in = &inner[k.object];
        }
        float *v = p->numbers(o);
        const std::vector<float> before(v, v + p->count);
        if (p->count == 1)
            r.number(*in, k.key, where, *v, p->lo, p->hi);
        else
            r.numbers(*in, k.key, where, v, p->count, p->lo, p->hi);
        const QString refused = p->refusal(v);
        if (!refused.isEmpty()) {
            r.ignore(SceneJsonReader::join(where, k.key), refused);
            std::copy(before.begin(), before.end(), v);
        }
    }
}

void readLight(SceneJsonReader &r, const QJsonObject &l, const QString &path, Light &light)
{
    const QJsonObject known = lightJson(light);
    r.unknownKeys(l, known, path);
    r.boolean(l, "enabled", path, light.enabled);
    r.word(l, "frame", path, parseLightFrame, light.frame);
    readParameters(r, l, path, ParameterOwner::Light, light, known);
    // Checked against the objects once they are read (fromJson): one message, not two.
    r.number(l, "object", path, light.object, 0, std::numeric_limits<int>::max());
}

void readMaterial(SceneJsonReader &r, const QJsonObject &m, const QString &path, Material &material)
{
    const QJsonObject known = materialJson(material);
    r.unknownKeys(m, known, path);
    readParameters(r, m, path, ParameterOwner::Material, material, known);
}

// One object; version 2's "object" is read by the same code (it has fewer fields).
void readObject(SceneJsonReader &r, const QJsonObject &ob, const QString &path,
                ObjectSettings &object)
{
    r.unknownKeys(ob, objectJson(object), path);
    r.name(ob, "name", path, object.name);
    r.boolean(ob, "visible", path, object.visible);
    r.word(ob, "shape", path, parseShape, object.shape);
    r.number(ob, "tessellation", path, object.tessellation, limits::kMinTessellation,
             limits::kMaxTessellation);
    r.numbers(ob, "rotation", path, &object.rotationDegrees.x, 3, -3600.0f, 3600.0f);
    r.numbers(ob, "scale", path, &object.scale.x, 3, limits::kMinScale, limits::kMaxScale);
    const float c = limits::kMaxCoordinate;
    r.numbers(ob, "translation", path, &object.translation.x, 3, -c, c);
    r.boolean(ob, "autoRotate", path, object.autoRotate);
    r.text(ob, "mesh", path, object.meshPath);
    r.word(ob, "normals", path, parseNormalMode, object.normals);
    r.word(ob, "faces", path, parseFaces, object.faces);
    r.number(ob, "creaseAngle", path, object.creaseDegrees, 0.0f, limits::kMaxCreaseDegrees);
    r.boolean(ob, "showNormals", path, object.showNormals);
    r.boolean(ob, "cullBackFaces", path, object.cullBackFaces);
    r.boolean(ob, "adoptFileMaterial", path, object.adoptFileMaterial);
    if (ob.contains("material"))
        readMaterial(r, r.object(ob, "material", SceneJsonReader::join(path, "material")),
                     SceneJsonReader::join(path, "material"), object.material);
    r.boolean(ob, "texture", path, object.texture);
    r.text(ob, "textureFile", path, object.textureFile);
    r.word(ob, "textureWrap", path, parseTextureWrap, object.sampling.wrap);
    r.word(ob, "textureFilter", path, parseTextureFilter, object.sampling.filter);
    r.boolean(ob, "textureMipmaps", path, object.sampling.mipmaps);
}

// "bindings": {"uniform name": "semantic key" or "none"}, at most limits::kMaxBindings.
void readBindings(SceneJsonReader &r, const QJsonObject &json, UniformBindings &bindings)
{
    for (auto it = json.begin(); it != json.end(); ++it) {
        if (int(bindings.size()) == limits::kMaxBindings) {
            r.ignore("bindings", SceneJsonMessages::tr("too many: %1 more than the %2 kept")
                                     .arg(json.size() - limits::kMaxBindings)
                                     .arg(limits::kMaxBindings));
            return;
        }
        if (it.key().isEmpty() || it.key().size() > limits::kMaxShaderValueName) {
            r.ignore("bindings." + it.key().left(40),
                     SceneJsonMessages::tr("not a uniform's name"));
            continue;
        }
        bool unbound = false;
        const std::optional<Semantic> semantic = semanticFromKey(it.value().toString(), &unbound);
        if (semantic || unbound)
            bindings[it.key()] = semantic;
        else
            r.ignore("bindings." + it.key(),
                     SceneJsonMessages::tr("not one of the values the scene feeds (%1)")
                         .arg(QStringList(semanticKeys() << kUnboundKey).join(", ")));
    }
}

} // namespace

QJsonObject Scene::toJson() const
{
    QJsonArray ls;
    for (const Light &light : lights)
        ls.append(lightJson(light));

    QJsonObject s;
    s["shading"] = toName(shading.shading);
    s["specular"] = toName(shading.specular);
    s["projection"] = toName(shading.projection);
    s["lighting"] = shading.lighting;
    s["terms"] = termsJson(shading.terms);
    s["show"] = toName(shading.show);
    s["vertexColors"] = shading.vertexColors;
    s["normalsByModelView"] = shading.normalsByModelView;

    QJsonArray obs;
    for (const ObjectSettings &object : objects)
        obs.append(objectJson(object));

    QJsonObject c;
    c["target"] = toArray(&camera.target.x, 3);
    c["distance"] = double(camera.distance);
    c["yaw"] = double(camera.yawDegrees);
    c["pitch"] = double(camera.pitchDegrees);

    QJsonObject cmp;
    cmp["mode"] = toName(compare.mode);
    cmp["wipe"] = double(compare.wipe);
    cmp["shading"] = toName(compare.shading);
    cmp["specular"] = toName(compare.specular);

    QJsonObject root;
    root["lights"] = ls;
    root["shading"] = s;
    root["objects"] = obs;
    root["selected"] = selected;
    root["camera"] = c;
    root["compare"] = cmp;
    root["showLight"] = showLight;
    QJsonObject values;
    for (const auto &[name, v] : shaderValues)
        values[name] = toArray(v.data(), int(v.size()));
    root["shaderValues"] = values;
    QJsonObject bound;
    for (const auto &[name, semantic] : bindings)
        bound[name] = semantic ? semanticKey(*semantic) : QString(kUnboundKey);
    root["bindings"] = bound;
    return root;
}

Scene Scene::fromJson(const QJsonObject &json, QStringList *ignored)
{
    Scene sc;
    SceneJsonReader r(ignored);
    const QJsonObject known = sc.toJson();
    QJsonObject knownRoot = known;
    knownRoot["light"] = QJsonObject();  // version 1 had a single light
    knownRoot["object"] = QJsonObject(); // versions 1 and 2 had one object and its material
    knownRoot["material"] = QJsonObject();
    r.unknownKeys(json, knownRoot, {});

    // Version 1 files and settings hold one light under "light".
    if (json.contains("light"))
        readLight(r, r.object(json, "light", "light"), "light", sc.lights[0]);
    if (json.contains("lights")) {
        const QJsonValue v = json.value("lights");
        const QJsonArray ls = v.toArray();
        if (!v.isArray())
            r.ignore("lights", SceneJsonMessages::tr("not an array"));
        for (int i = 0; i < int(ls.size()); ++i) {
            const QString path = QString("lights[%1]").arg(i);
            if (i >= kMaxLights)
                r.ignore(path, SceneJsonMessages::tr("at most 4 lights"));
            else if (!ls[i].isObject())
                r.ignore(path, SceneJsonMessages::tr("not an object"));
            else
                readLight(r, ls[i].toObject(), path, sc.lights[std::size_t(i)]);
        }
    }

    const QJsonObject s = r.object(json, "shading", "shading");
    QJsonObject knownShading = known["shading"].toObject();
    knownShading["texture"] = false; // version 2's texture switch, now each object's
    r.unknownKeys(s, knownShading, "shading");
    r.word(s, "shading", "shading", parseShading, sc.shading.shading);
    r.word(s, "specular", "shading", parseSpecularModel, sc.shading.specular);
    r.word(s, "projection", "shading", parseProjection, sc.shading.projection);
    r.boolean(s, "lighting", "shading", sc.shading.lighting);
    const QJsonObject terms = r.object(s, "terms", "shading.terms");
    r.unknownKeys(terms, termsJson(sc.shading.terms), "shading.terms");
    r.boolean(terms, "ambient", "shading.terms", sc.shading.terms.ambient);
    r.boolean(terms, "diffuse", "shading.terms", sc.shading.terms.diffuse);
    r.boolean(terms, "specular", "shading.terms", sc.shading.terms.specular);
    r.word(s, "show", "shading", parseShowChoice, sc.shading.show);
    r.boolean(s, "vertexColors", "shading", sc.shading.vertexColors);
    r.boolean(s, "normalsByModelView", "shading", sc.shading.normalsByModelView);

    if (json.contains("objects")) {
        const QJsonValue v = json.value("objects");
        const QJsonArray obs = v.toArray();
        if (!v.isArray())
            r.ignore("objects", SceneJsonMessages::tr("not an array"));
        else if (obs.isEmpty())
            r.ignore("objects", SceneJsonMessages::tr("empty: one object drawn instead"));
        std::vector<ObjectSettings> read;
        for (int i = 0; i < int(obs.size()); ++i) {
            const QString path = QString("objects[%1]").arg(i);
            if (int(read.size()) >= kMaxObjects) {
                r.ignore(path, SceneJsonMessages::tr("at most 32 objects; the rest left out"));
                break;
            }
            read.emplace_back(); // in its place, so that the indices after it stay right
            if (!obs[i].isObject()) {
                r.ignore(path, SceneJsonMessages::tr("not an object; a sphere in its place"));
                continue;
            }
            readObject(r, obs[i].toObject(), path, read.back());
        }
        if (!read.empty())
            sc.objects = std::move(read);
    } else {
        // Versions 1 and 2: one object, the material and the texture switch apart from it.
        ObjectSettings &only = sc.objects.front();
        if (json.contains("object"))
            readObject(r, r.object(json, "object", "object"), "object", only);
        if (json.contains("material"))
            readMaterial(r, r.object(json, "material", "material"), "material", only.material);
        r.boolean(s, "texture", "shading", only.texture);
    }
    const int last = int(sc.objects.size()) - 1;
    r.number(json, "selected", {}, sc.selected, 0, last);
    for (int i = 0; i < kMaxLights; ++i) {
        Light &light = sc.lights[std::size_t(i)];
        if (light.object > last) {
            r.ignore(QString("lights[%1].object").arg(i),
                     SceneJsonMessages::tr("no such object; the first one"));
            light.object = 0;
        }
    }

    const QJsonObject c = r.object(json, "camera", "camera");
    r.unknownKeys(c, known["camera"].toObject(), "camera");
    const float far = limits::kMaxCoordinate;
    r.numbers(c, "target", "camera", &sc.camera.target.x, 3, -far, far);
    r.number(c, "distance", "camera", sc.camera.distance, 0.0f, far);
    r.number(c, "yaw", "camera", sc.camera.yawDegrees, -3600.0f, 3600.0f);
    r.number(c, "pitch", "camera", sc.camera.pitchDegrees, -90.0f, 90.0f);
    // Re-apply the camera's own limits to whatever the file held.
    sc.camera.zoom(0.0f);
    sc.camera.orbit(0.0f, 0.0f);

    const QJsonObject cmp = r.object(json, "compare", "compare");
    r.unknownKeys(cmp, known["compare"].toObject(), "compare");
    r.word(cmp, "mode", "compare", parseCompareMode, sc.compare.mode);
    r.number(cmp, "wipe", "compare", sc.compare.wipe, 0.0f, 1.0f);
    r.word(cmp, "shading", "compare", parseShading, sc.compare.shading);
    r.word(cmp, "specular", "compare", parseSpecularModel, sc.compare.specular);

    r.boolean(json, "showLight", {}, sc.showLight);
    const QJsonObject values = r.object(json, "shaderValues", "shaderValues");
    int kept = 0;
    for (auto it = values.begin(); it != values.end(); ++it) {
        if (kept == limits::kMaxShaderValues) {
            r.ignore("shaderValues", SceneJsonMessages::tr("too many: %1 more than the %2 kept")
                                         .arg(values.size() - kept)
                                         .arg(limits::kMaxShaderValues));
            break;
        }
        if (it.key().isEmpty() || it.key().size() > limits::kMaxShaderValueName) {
            r.ignore("shaderValues." + it.key().left(40),
                     SceneJsonMessages::tr("not a uniform's name"));
            continue;
        }
        const QJsonArray a = it.value().toArray();
        const int n = int(a.size());
        std::vector<float> v(std::size_t(std::clamp(n, 1, 4)), 0.0f);
        QStringList bad;
        SceneJsonReader one(&bad);
        if (n >= 1 && n <= 4)
            one.numbers(values, it.key(), {}, v.data(), n, -3.4e38f, 3.4e38f);
        if (n >= 1 && n <= 4 && bad.isEmpty()) {
            sc.shaderValues[it.key()] = v;
            ++kept;
        } else
            r.ignore("shaderValues." + it.key(), SceneJsonMessages::tr("not 1 to 4 numbers"));
    }
    readBindings(r, r.object(json, "bindings", "bindings"), sc.bindings);
    return sc;
}

} // namespace lb
