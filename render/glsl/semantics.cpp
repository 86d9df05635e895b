#include "semantics.h"

#include <utility>

namespace lb {

namespace {

const std::pair<const char *, Semantic> kTable[] = {
    {"mModelView", Semantic::ModelView},
    {"uModelViewMatrix", Semantic::ModelView},
    {"mNormals", Semantic::Normals},
    {"uNormalMatrix", Semantic::Normals},
    {"mView", Semantic::View},
    {"mViewNormals", Semantic::ViewNormals},
    {"mProjection", Semantic::Projection},
    {"uProjectionMatrix", Semantic::Projection},
    {"lightPosition", Semantic::LightPosition},
    {"uLightPosition", Semantic::LightPositionEye},
    {"lightAmb", Semantic::LightAmbient},
    {"lightDif", Semantic::LightDiffuse},
    {"uLightColor", Semantic::LightDiffuse},
    {"lightSpe", Semantic::LightSpecular},
    {"materialAmb", Semantic::MaterialAmbient},
    {"materialDif", Semantic::MaterialDiffuse},
    {"materialSpe", Semantic::MaterialSpecular},
    {"shininess", Semantic::Shininess},
    {"uLightFrame", Semantic::LightFrame},
    {"uLightEnabled", Semantic::LightEnabled},
    {"uSpecularModel", Semantic::SpecularModel},
    {"uProjection", Semantic::ProjectionKind},
    {"uEnableLighting", Semantic::EnableLighting},
    {"uEnableVertexColor", Semantic::EnableVertexColor},
    {"uEnableTexture", Semantic::EnableTexture},
    {"uSampler", Semantic::Sampler},
    {"lightAttenuation", Semantic::LightAttenuation},
    {"spotDirection", Semantic::SpotDirection},
    {"spotCutoff", Semantic::SpotCutoff},
    {"spotCosCutoff", Semantic::SpotCosCutoff},
    {"spotExponent", Semantic::SpotExponent},
    {"uEnableAmbient", Semantic::EnableAmbient},
    {"uEnableDiffuse", Semantic::EnableDiffuse},
    {"uEnableSpecular", Semantic::EnableSpecular},
    {"uShow", Semantic::Show},
};

} // namespace

std::optional<Semantic> semanticOf(const QString &uniformName)
{
    for (const auto &[name, semantic] : kTable)
        if (uniformName == QLatin1String(name))
            return semantic;
    return std::nullopt;
}

QStringList uniformNames(Semantic semantic)
{
    QStringList names;
    for (const auto &[name, s] : kTable)
        if (s == semantic)
            names << QString::fromLatin1(name);
    return names;
}

bool isPerLight(Semantic semantic)
{
    switch (semantic) {
    case Semantic::LightPosition:
    case Semantic::LightPositionEye:
    case Semantic::LightAmbient:
    case Semantic::LightDiffuse:
    case Semantic::LightSpecular:
    case Semantic::LightFrame:
    case Semantic::LightEnabled:
    case Semantic::LightAttenuation:
    case Semantic::SpotDirection:
    case Semantic::SpotCutoff:
    case Semantic::SpotCosCutoff:
    case Semantic::SpotExponent:
        return true;
    default:
        return false;
    }
}

} // namespace lb
