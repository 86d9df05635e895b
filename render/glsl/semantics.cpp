#include "semantics.h"

#include <utility>

namespace lb {

std::optional<Semantic> semanticOf(const QString &uniformName)
{
    static const std::pair<const char *, Semantic> table[] = {
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
    };
    for (const auto &[name, semantic] : table)
        if (uniformName == QLatin1String(name))
            return semantic;
    return std::nullopt;
}

} // namespace lb
