#include "scene.h"

#include <tuple>

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace lb {

namespace {

template <typename E, std::size_t N> using NameTable = std::array<std::pair<E, const char *>, N>;

constexpr NameTable<LightFrame, 3> kFrames{
    {{LightFrame::Camera, "camera"}, {LightFrame::World, "world"}, {LightFrame::Object, "object"}}};
constexpr NameTable<Shading, 3> kShadings{
    {{Shading::Gouraud, "gouraud"}, {Shading::Phong, "phong"}, {Shading::Flat, "flat"}}};
constexpr NameTable<Projection, 2> kProjections{
    {{Projection::Perspective, "perspective"}, {Projection::Orthographic, "orthographic"}}};
constexpr NameTable<Shape, 4> kShapes{{{Shape::Cube, "cube"},
                                       {Shape::Sphere, "sphere"},
                                       {Shape::Torus, "torus"},
                                       {Shape::Plane, "plane"}}};
constexpr NameTable<NormalMode, 3> kNormalModes{
    {{NormalMode::File, "file"}, {NormalMode::Smooth, "smooth"}, {NormalMode::Flat, "flat"}}};
constexpr NameTable<Faces, 4> kFaces{{{Faces::Outward, "outward"},
                                      {Faces::File, "file"},
                                      {Faces::Flipped, "flipped"},
                                      {Faces::TwoSided, "two-sided"}}};
constexpr NameTable<CompareMode, 4> kCompareModes{{{CompareMode::Off, "off"},
                                                   {CompareMode::SideBySide, "side-by-side"},
                                                   {CompareMode::Wipe, "wipe"},
                                                   {CompareMode::Difference, "difference"}}};

constexpr NameTable<TextureWrap, 2> kTextureWraps{
    {{TextureWrap::Repeat, "repeat"}, {TextureWrap::Clamp, "clamp"}}};
constexpr NameTable<TextureFilter, 2> kTextureFilters{
    {{TextureFilter::Nearest, "nearest"}, {TextureFilter::Linear, "linear"}}};

constexpr NameTable<ShowChoice, 9> kShowChoices{{{ShowChoice::Colour, "colour"},
                                                 {ShowChoice::Normal, "normal"},
                                                 {ShowChoice::Light, "light"},
                                                 {ShowChoice::View, "view"},
                                                 {ShowChoice::Half, "half"},
                                                 {ShowChoice::Reflect, "reflect"},
                                                 {ShowChoice::NDotL, "ndotl"},
                                                 {ShowChoice::Specular, "specular"},
                                                 {ShowChoice::Attenuation, "attenuation"}}};

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

// Every field of ObjectSettings but its material (which is ScenePart::Material).
bool sameExceptMaterial(const ObjectSettings &a, const ObjectSettings &b)
{
    return std::tie(a.name, a.visible, a.shape, a.tessellation, a.meshPath, a.normals,
                    a.creaseDegrees, a.faces, a.showNormals, a.cullBackFaces, a.adoptFileMaterial,
                    a.rotationDegrees, a.scale, a.translation, a.autoRotate, a.texture,
                    a.textureFile, a.sampling) ==
           std::tie(b.name, b.visible, b.shape, b.tessellation, b.meshPath, b.normals,
                    b.creaseDegrees, b.faces, b.showNormals, b.cullBackFaces, b.adoptFileMaterial,
                    b.rotationDegrees, b.scale, b.translation, b.autoRotate, b.texture,
                    b.textureFile, b.sampling);
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
QString toName(Faces v)
{
    return nameOf(kFaces, v);
}
QString toName(CompareMode v)
{
    return nameOf(kCompareModes, v);
}
QString toName(ShowChoice v)
{
    return nameOf(kShowChoices, v);
}
QString toName(TextureWrap v)
{
    return nameOf(kTextureWraps, v);
}
QString toName(TextureFilter v)
{
    return nameOf(kTextureFilters, v);
}
std::optional<LightFrame> parseLightFrame(const QString &s)
{
    return valueOf(kFrames, s);
}
std::optional<Shading> parseShading(const QString &s)
{
    return valueOf(kShadings, s);
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
std::optional<Faces> parseFaces(const QString &s)
{
    return valueOf(kFaces, s);
}
std::optional<CompareMode> parseCompareMode(const QString &s)
{
    return valueOf(kCompareModes, s);
}
std::optional<ShowChoice> parseShowChoice(const QString &s)
{
    return valueOf(kShowChoices, s);
}
std::optional<TextureWrap> parseTextureWrap(const QString &s)
{
    return valueOf(kTextureWraps, s);
}
std::optional<TextureFilter> parseTextureFilter(const QString &s)
{
    return valueOf(kTextureFilters, s);
}
QStringList lightFrameNames()
{
    return namesOf(kFrames);
}
QStringList shadingNames()
{
    return namesOf(kShadings);
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
QStringList facesNames()
{
    return namesOf(kFaces);
}
QStringList compareModeNames()
{
    return namesOf(kCompareModes);
}
QStringList showChoiceNames()
{
    return namesOf(kShowChoices);
}
QStringList textureWrapNames()
{
    return namesOf(kTextureWraps);
}
QStringList textureFilterNames()
{
    return namesOf(kTextureFilters);
}

// Every field of each struct: a field added to one of them must be added here too (the
// scene test saves and reads back a scene that differs from the defaults in every field).
bool operator==(const LightColors &a, const LightColors &b)
{
    return std::tie(a.ia, a.id, a.is) == std::tie(b.ia, b.id, b.is);
}

bool operator==(const Spot &a, const Spot &b)
{
    return std::tie(a.direction, a.cutoffDegrees, a.exponent) ==
           std::tie(b.direction, b.cutoffDegrees, b.exponent);
}

bool operator==(const Light &a, const Light &b)
{
    // The numbers are the table's (lighting_parameters.h); the rest is the light's own.
    return sameParameters(a, b) &&
           std::tie(a.frame, a.enabled, a.object) == std::tie(b.frame, b.enabled, b.object);
}

bool operator==(const TermSwitches &a, const TermSwitches &b)
{
    return std::tie(a.ambient, a.diffuse, a.specular) == std::tie(b.ambient, b.diffuse, b.specular);
}

bool operator==(const Material &a, const Material &b)
{
    return sameParameters(a, b); // all its members are the table's numbers
}

bool operator==(const ShadingSettings &a, const ShadingSettings &b)
{
    return std::tie(a.shading, a.specular, a.projection, a.lighting, a.terms, a.show,
                    a.vertexColors, a.normalsByModelView) ==
           std::tie(b.shading, b.specular, b.projection, b.lighting, b.terms, b.show,
                    b.vertexColors, b.normalsByModelView);
}

bool operator==(const ObjectSettings &a, const ObjectSettings &b)
{
    return sameExceptMaterial(a, b) && a.material == b.material;
}

bool operator==(const OrbitCamera &a, const OrbitCamera &b)
{
    return std::tie(a.target, a.distance, a.yawDegrees, a.pitchDegrees) ==
           std::tie(b.target, b.distance, b.yawDegrees, b.pitchDegrees);
}

bool operator==(const CompareSettings &a, const CompareSettings &b)
{
    return std::tie(a.mode, a.wipe, a.shading, a.specular) ==
           std::tie(b.mode, b.wipe, b.shading, b.specular);
}

SceneParts differingParts(const Scene &a, const Scene &b)
{
    SceneParts parts;
    parts.setFlag(ScenePart::Lights, a.lights != b.lights || a.showLight != b.showLight);
    bool materials = a.objects.size() != b.objects.size() || a.selected != b.selected;
    bool objects = materials;
    for (std::size_t i = 0; i < std::min(a.objects.size(), b.objects.size()); ++i) {
        materials = materials || !(a.objects[i].material == b.objects[i].material);
        objects = objects || !sameExceptMaterial(a.objects[i], b.objects[i]);
    }
    // Another object selected: the Material panel shows another material.
    parts.setFlag(ScenePart::Material, materials);
    parts.setFlag(ScenePart::Shading, !(a.shading == b.shading));
    parts.setFlag(ScenePart::Object, objects);
    parts.setFlag(ScenePart::Camera, !(a.camera == b.camera));
    parts.setFlag(ScenePart::Compare, !(a.compare == b.compare));
    parts.setFlag(ScenePart::Program, a.shaderValues != b.shaderValues);
    parts.setFlag(ScenePart::Bindings, a.bindings != b.bindings);
    return parts;
}

bool addObject(Scene &scene, const ObjectSettings &object)
{
    if (int(scene.objects.size()) >= kMaxObjects)
        return false;
    scene.objects.push_back(object);
    scene.selected = int(scene.objects.size()) - 1;
    return true;
}

bool removeObject(Scene &scene, int index)
{
    if (scene.objects.size() <= 1 || index < 0 || index >= int(scene.objects.size()))
        return false;
    scene.objects.erase(scene.objects.begin() + index);
    for (Light &light : scene.lights)
        if (light.object >= index && light.object > 0)
            --light.object;
    if (scene.selected >= index && scene.selected > 0)
        --scene.selected;
    return true;
}

glm::vec3 freePlace(const Scene &scene)
{
    constexpr float kSpacing = 2.5f;
    const auto free = [&](const glm::vec3 &p) {
        return std::none_of(scene.objects.begin(), scene.objects.end(),
                            [&](const auto &o) { return glm::length(o.translation - p) < 2.0f; });
    };
    // 0, 1, -1, 2, -2, ...: the k-th step out from the middle.
    const auto outward = [](int k) { return k % 2 ? (k + 1) / 2 : -(k / 2); };
    // Square rings around the origin, nearest first; in each, the row through the origin
    // first, then those above and below, each from the middle out.
    for (int ring = 0; ring < 64; ++ring)
        for (int ky = 0; ky <= 2 * ring; ++ky)
            for (int kx = 0; kx <= 2 * ring; ++kx) {
                const int x = outward(kx), y = outward(ky);
                const glm::vec3 p(kSpacing * float(x), kSpacing * float(y), 0.0f);
                if (std::max(std::abs(x), std::abs(y)) == ring && free(p))
                    return p;
            }
    return glm::vec3(0.0f);
}

void placeInRow(std::vector<ObjectSettings> &objects)
{
    const float middle = 0.5f * float(objects.size() - 1);
    for (std::size_t i = 0; i < objects.size(); ++i)
        objects[i].translation = glm::vec3(2.5f * (float(i) - middle), 0.0f, 0.0f);
}

void frameScene(Scene &scene)
{
    // Every shape and mesh file fits the cube from -1 to 1 (meshes are scaled to it when
    // read): a sphere of radius sqrt(3) times the largest scale holds it, however turned.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    std::vector<std::pair<glm::vec3, float>> spheres;
    for (const ObjectSettings &o : scene.objects)
        if (o.visible) {
            const glm::vec3 a = glm::abs(o.scale);
            const float r = std::sqrt(3.0f) * std::max({a.x, a.y, a.z});
            spheres.emplace_back(o.translation, r);
            lo = glm::min(lo, o.translation - r);
            hi = glm::max(hi, o.translation + r);
        }
    OrbitCamera camera;
    if (!spheres.empty()) {
        camera.target = 0.5f * (lo + hi);
        float radius = 0.0f;
        for (const auto &[centre, r] : spheres)
            radius = std::max(radius, glm::length(centre - camera.target) + r);
        // The default distance shows one unscaled object well, with room to spare; a bounding
        // sphere of several is looser than theirs (a row is wider than it is tall, as views
        // are), so it comes in closer by 0.85, as far as a narrow view allows.
        const float closer = spheres.size() > 1 ? 0.85f : 1.0f;
        camera.distance =
            std::clamp(closer * camera.distance * radius / std::sqrt(3.0f), camera.distance, 50.0f);
    }
    scene.camera = camera;
}

QString displayName(const ObjectSettings &object)
{
    if (!object.name.isEmpty())
        return localized(object.name, lessonLanguage());
    if (!object.meshPath.isEmpty())
        return QFileInfo(object.meshPath).fileName();
    return shapeLabel(object.shape);
}

QString shapeLabel(Shape shape)
{
    switch (shape) {
    case Shape::Cube:
        return QCoreApplication::translate("lb::Scene", "cube");
    case Shape::Sphere:
        return QCoreApplication::translate("lb::Scene", "sphere");
    case Shape::Torus:
        return QCoreApplication::translate("lb::Scene", "torus");
    case Shape::Plane:
        return QCoreApplication::translate("lb::Scene", "plane");
    }
    return toName(shape);
}

bool operator==(const Scene &a, const Scene &b)
{
    return !differingParts(a, b);
}

} // namespace lb
