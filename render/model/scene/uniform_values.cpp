#include "uniform_values.h"

#include <algorithm>

namespace lb {

namespace {

UniformValue colour(const Light &l, const glm::vec3 &c)
{
    return UniformValue::ofVector(glm::vec4(l.enabled ? c : glm::vec3(0.0f), 1.0f));
}

} // namespace

UniformValue uniformValue(Semantic semantic, const Scene &scene, const Frames &frames, int light)
{
    light = std::clamp(light, 0, kMaxLights - 1);
    const Light &l = scene.lights[std::size_t(light)];
    const ObjectSettings &object = scene.objects[std::size_t(frames.object)];
    const Material &m = object.material;
    const ShadingSettings &s = scene.shading;
    switch (semantic) {
    case Semantic::ModelView:
        return UniformValue::ofMatrix(frames.modelView);
    case Semantic::Normals:
        return UniformValue::ofMatrix(frames.normals);
    case Semantic::View:
        return UniformValue::ofMatrix(frames.view);
    case Semantic::ViewNormals:
        return UniformValue::ofMatrix(frames.viewNormals);
    case Semantic::Projection:
        return UniformValue::ofMatrix(frames.projection);
    case Semantic::LightPosition:
        return UniformValue::ofVector(lightForDrawnObject(frames, light, l.position, l.frame));
    case Semantic::LightPositionEye:
        return UniformValue::ofVector(lightInEye(frames, light, l.position, l.frame));
    case Semantic::LightAmbient:
        return colour(l, l.colors.ia);
    case Semantic::LightDiffuse:
        return colour(l, l.colors.id);
    case Semantic::LightSpecular:
        return colour(l, l.colors.is);
    case Semantic::LightFrame:
        return UniformValue::ofNumber(float(int(l.frame)));
    case Semantic::LightEnabled:
        return UniformValue::ofNumber(l.enabled ? 1.0f : 0.0f);
    case Semantic::MaterialAmbient:
        return UniformValue::ofVector(glm::vec4(m.ka, 1.0f));
    case Semantic::MaterialDiffuse:
        return UniformValue::ofVector(glm::vec4(m.kd, 1.0f));
    case Semantic::MaterialSpecular:
        return UniformValue::ofVector(glm::vec4(m.ks, 1.0f));
    case Semantic::Shininess:
        return UniformValue::ofNumber(m.shininess);
    case Semantic::SpecularModel:
        return UniformValue::ofNumber(s.specular == SpecularModel::Blinn ? 1.0f : 0.0f);
    case Semantic::ProjectionKind:
        return UniformValue::ofNumber(s.projection == Projection::Perspective ? 0.0f : 1.0f);
    case Semantic::EnableLighting:
        return UniformValue::ofNumber(s.lighting ? 1.0f : 0.0f);
    case Semantic::EnableVertexColor:
        return UniformValue::ofNumber(s.vertexColors ? 1.0f : 0.0f);
    case Semantic::EnableTexture:
        return UniformValue::ofNumber(object.texture ? 1.0f : 0.0f);
    case Semantic::Sampler:
        return UniformValue::ofNumber(0.0f); // the object's texture is bound to unit 0
    case Semantic::LightAttenuation:
        return UniformValue::ofVector(glm::vec4(l.attenuation, 0.0f));
    case Semantic::SpotDirection:
        return UniformValue::ofVector(
            lightForDrawnObject(frames, light, glm::vec4(l.spot.direction, 0.0f), l.frame));
    case Semantic::SpotCutoff:
        return UniformValue::ofNumber(l.spot.cutoffDegrees);
    case Semantic::SpotCosCutoff:
        return UniformValue::ofNumber(spotCosCutoff(l.spot));
    case Semantic::SpotExponent:
        return UniformValue::ofNumber(l.spot.exponent);
    case Semantic::EnableAmbient:
        return UniformValue::ofNumber(s.terms.ambient ? 1.0f : 0.0f);
    case Semantic::EnableDiffuse:
        return UniformValue::ofNumber(s.terms.diffuse ? 1.0f : 0.0f);
    case Semantic::EnableSpecular:
        return UniformValue::ofNumber(s.terms.specular ? 1.0f : 0.0f);
    case Semantic::Show:
        return UniformValue::ofNumber(float(int(s.show)));
    }
    return {};
}

} // namespace lb
