#include "bindings.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>

namespace lb {

namespace {

using S = Semantic;
using Sh = UniformShape;

struct SemanticRow
{
    Semantic semantic;
    const char *key;
    UniformShape shape;
    const char *label;
};

// One row a semantic, in the enum's order (row() indexes it; test_bindings checks it).
const SemanticRow kSemantics[] = {
    {S::ModelView, "model-view", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Model-view matrix (camera from object)")},
    {S::Normals, "normal-matrix", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Normal matrix (inverse transpose of model-view)")},
    {S::View, "view", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "View matrix (camera from world)")},
    {S::ViewNormals, "view-normals", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "View's normal matrix (inverse transpose of view)")},
    {S::Projection, "projection", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Projection matrix")},
    {S::LightPosition, "light-position", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light position, in the Light panel's frame (x, y, z, w)")},
    {S::LightPositionEye, "light-position-camera", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light position (camera coordinates)")},
    {S::LightAmbient, "light-ambient", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light's ambient colour Ia")},
    {S::LightDiffuse, "light-diffuse", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light's diffuse colour Id")},
    {S::LightSpecular, "light-specular", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light's specular colour Is")},
    {S::MaterialAmbient, "material-ambient", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Material's ambient colour Ka")},
    {S::MaterialDiffuse, "material-diffuse", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Material's diffuse colour Kd")},
    {S::MaterialSpecular, "material-specular", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Material's specular colour Ks")},
    {S::Shininess, "shininess", Sh::Number, QT_TRANSLATE_NOOP("lb::Bindings", "Shininess")},
    {S::LightFrame, "light-frame", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light's frame (0 camera, 1 world, 2 object)")},
    {S::LightEnabled, "light-enabled", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light on (1) or off (0)")},
    {S::SpecularModel, "specular-model", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Specular model (0 Phong, 1 Blinn-Phong)")},
    {S::ProjectionKind, "projection-kind", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Projection (0 perspective, 1 parallel)")},
    {S::EnableLighting, "enable-lighting", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Lighting on (1) or off (0)")},
    {S::EnableVertexColor, "enable-vertex-color", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Vertex colours on (1) or off (0)")},
    {S::EnableTexture, "enable-texture", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Texture on (1) or off (0)")},
    {S::Sampler, "texture", Sh::Sampler,
     QT_TRANSLATE_NOOP("lb::Bindings", "The object's texture (unit 0)")},
    {S::LightAttenuation, "attenuation", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Attenuation (kc, kl, kq)")},
    {S::SpotDirection, "spot-direction", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Spot's axis, in the light's frame")},
    {S::SpotCutoff, "spot-cutoff", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Spot's cut-off angle (degrees)")},
    {S::SpotCosCutoff, "spot-cos-cutoff", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Cosine of the spot's cut-off angle")},
    {S::SpotExponent, "spot-exponent", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Spot's exponent")},
    {S::EnableAmbient, "enable-ambient", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Ambient term on (1) or off (0)")},
    {S::EnableDiffuse, "enable-diffuse", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Diffuse term on (1) or off (0)")},
    {S::EnableSpecular, "enable-specular", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Specular term on (1) or off (0)")},
    {S::Show, "show", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Show choice (0 the colour, 1 N, 2 L...)")},
    {S::Model, "model", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Model matrix (world from object)")},
    {S::ModelNormals, "model-normals", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Model's normal matrix (inverse transpose of model)")},
    {S::ViewProjection, "view-projection", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Projection times view")},
    {S::ModelViewProjection, "model-view-projection", Sh::Matrix,
     QT_TRANSLATE_NOOP("lb::Bindings", "Projection times model-view (MVP)")},
    {S::LightPositionWorld, "light-position-world", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Light position (world coordinates)")},
    {S::LightDirectionWorld, "light-direction-world", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Direction the light shines (world)")},
    {S::ReverseLightDirection, "reverse-light-direction", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Direction towards the light (world, unit)")},
    {S::CameraPositionWorld, "camera-position-world", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Camera position (world coordinates)")},
    {S::AmbientProduct, "ambient-product", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Ia times Ka")},
    {S::DiffuseProduct, "diffuse-product", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Id times Kd")},
    {S::SpecularProduct, "specular-product", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Is times Ks")},
    {S::AttenuationConstant, "attenuation-constant", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Attenuation's constant factor kc")},
    {S::AttenuationLinear, "attenuation-linear", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Attenuation's linear factor kl")},
    {S::AttenuationQuadratic, "attenuation-quadratic", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Attenuation's quadratic factor kq")},
    {S::SpotDirectionEye, "spot-direction-camera", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings", "Spot's axis (camera coordinates)")},
    {S::HalfVectorEye, "half-vector-camera", Sh::Number,
     QT_TRANSLATE_NOOP("lb::Bindings",
                       "Half vector of a viewer far along +z (camera coordinates)")},
};
static_assert(std::size(kSemantics) == std::size_t(kLastSemantic) + 1,
              "one row for every semantic");

const SemanticRow &row(Semantic semantic)
{
    return kSemantics[std::size_t(semantic)];
}

struct BindingMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Bindings)
};

// The words of a name, lower case, with the short forms tutorials use spelled as the keys
// spell them: uLightPos -> u, light, pos; u_eyePosition -> u, camera, position; objectColor
// -> object, diffuse; Kd -> material, diffuse.
QStringList wordsOf(const QString &name)
{
    static const QRegularExpression boundary("(?<=[a-z0-9])(?=[A-Z])|[^A-Za-z0-9]+");
    static const std::pair<const char *, const char *> aliases[] = {
        {"color", "diffuse"},       {"colour", "diffuse"},      {"col", "diffuse"},
        {"eye", "camera"},          {"cam", "camera"},          {"mvp", "model view projection"},
        {"ka", "material ambient"}, {"kd", "material diffuse"}, {"ks", "material specular"},
        {"dir", "direction"},       {"object", "material"},     {"obj", "material"},
        {"lamp", "light"},          {"sun", "light"},
    };
    QStringList words;
    for (const QString &w : name.split(boundary, Qt::SkipEmptyParts)) {
        const QString lower = w.toLower();
        const auto alias = std::find_if(std::begin(aliases), std::end(aliases), [&](const auto &a) {
            return lower == QLatin1String(a.first);
        });
        if (alias == std::end(aliases))
            words << lower;
        else
            words << QString::fromLatin1(alias->second).split(' ');
    }
    return words;
}

// How well a name's words match a key's: twice the number of its words (of 3 letters or
// more) that begin a word of the key ("pos" begins "position"), and one more when they come
// in the key's order (eye position: camera-position-world before light-position-camera). 0
// for none. The switches (enable-diffuse) only for a name that says enable or use.
int matchScore(const QStringList &nameWords, const QString &key)
{
    const QStringList keyWords = key.split('-');
    if (keyWords.front() == QLatin1String("enable") &&
        std::none_of(nameWords.begin(), nameWords.end(), [](const QString &w) {
            return w.startsWith(QLatin1String("enable")) || w == QLatin1String("use");
        }))
        return 0;
    int matched = 0;
    int last = -1;
    bool inOrder = true;
    for (const QString &w : nameWords) {
        if (w.size() < 3)
            continue;
        const auto k = std::find_if(keyWords.begin(), keyWords.end(),
                                    [&](const QString &kw) { return kw.startsWith(w); });
        if (k == keyWords.end())
            continue;
        ++matched;
        const int at = int(k - keyWords.begin());
        inOrder = inOrder && at > last;
        last = at;
    }
    return matched == 0 ? 0 : 2 * matched + (inOrder ? 1 : 0);
}

} // namespace

QString semanticKey(Semantic semantic)
{
    return QString::fromLatin1(row(semantic).key);
}

std::optional<Semantic> semanticFromKey(const QString &key, bool *unbound)
{
    if (unbound)
        *unbound = key == QLatin1String(kUnboundKey);
    for (const SemanticRow &r : kSemantics)
        if (key == QLatin1String(r.key))
            return r.semantic;
    return std::nullopt;
}

QStringList semanticKeys()
{
    QStringList keys;
    for (const SemanticRow &r : kSemantics)
        keys << QString::fromLatin1(r.key);
    return keys;
}

QString semanticLabel(Semantic semantic)
{
    return QCoreApplication::translate("lb::Bindings", row(semantic).label);
}

UniformShape shapeOf(Semantic semantic)
{
    return row(semantic).shape;
}

bool fits(Semantic semantic, const ActiveUniform &uniform)
{
    return uniform.kind != UniformKind::Other && shapeOf(semantic) == shapeOf(uniform.kind);
}

std::vector<Diagnostic> applyBindings(std::vector<ActiveUniform> &uniforms,
                                      const UniformBindings &bindings)
{
    std::vector<Diagnostic> warnings;
    for (ActiveUniform &u : uniforms) {
        u.byName = u.semantic;
        const auto it = bindings.find(u.name);
        if (it == bindings.end())
            continue;
        if (it->second && !fits(*it->second, u)) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            //: %1 the uniform's name, %2 the key chosen for it (model-view, light-diffuse)
            d.message = BindingMessages::tr("the binding %1=%2 is not used: %1 is not of the "
                                            "type that %2 gives (a matrix, numbers, a texture)")
                            .arg(u.name, semanticKey(*it->second));
            warnings.push_back(d);
            continue;
        }
        u.semantic = it->second;
        u.bound = true;
    }
    return warnings;
}

std::vector<Semantic> suggestedSemantics(const QString &name, UniformShape shape)
{
    const QStringList words = wordsOf(name);
    std::vector<std::pair<int, Semantic>> scored;
    int best = 1;
    for (const SemanticRow &r : kSemantics)
        if (r.shape == shape)
            if (const int n = matchScore(words, QString::fromLatin1(r.key)); n > 0) {
                scored.push_back({n, r.semantic});
                best = std::max(best, n);
            }
    // Those that match best; of them the shortest keys first (view before model-view for
    // uWorldToView: all of view's words are matched), else in the table's order.
    std::vector<Semantic> found;
    for (const auto &[n, semantic] : scored)
        if (n == best)
            found.push_back(semantic);
    std::stable_sort(found.begin(), found.end(), [](Semantic a, Semantic b) {
        return semanticKey(a).count('-') < semanticKey(b).count('-');
    });
    return found;
}

} // namespace lb
