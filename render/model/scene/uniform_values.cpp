#include "uniform_values.h"

#include "legacy_builtins.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace lb {

static_assert(kLegacyLights == kMaxLights, "gl_LightSource holds the scene's lights");

namespace {

UniformValue colour(const Light &l, const glm::vec3 &c)
{
    return UniformValue::ofVector(glm::vec4(l.enabled ? c : glm::vec3(0.0f), 1.0f));
}

// Light `index`'s position or direction (by its w) in world coordinates.
glm::vec4 lightInWorld(const Frames &frames, int index, const glm::vec4 &light, LightFrame frame)
{
    return eyeToFrame(frames, index, lightInEye(frames, index, light, frame), LightFrame::World);
}

glm::vec3 unit(const glm::vec3 &v)
{
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f, 0.0f, 1.0f);
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
        return UniformValue::ofNumber(float(specularModel(s.specular).uniform));
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
    case Semantic::Model:
        return UniformValue::ofMatrix(frames.model);
    case Semantic::ModelNormals:
        return UniformValue::ofMatrix(normalMatrix(frames.model));
    case Semantic::ViewProjection:
        return UniformValue::ofMatrix(frames.projection * frames.view);
    case Semantic::ModelViewProjection:
        return UniformValue::ofMatrix(frames.projection * frames.modelView);
    case Semantic::LightPositionWorld:
        return UniformValue::ofVector(lightInWorld(frames, light, l.position, l.frame));
    case Semantic::LightDirectionWorld: {
        // Where the light shines: a directional light away from where it is (-L), any other
        // along its spot's axis (a light that is no spot shines along it too, uncut).
        if (l.position.w == 0.0f)
            return UniformValue::ofVector(
                glm::vec4(-unit(glm::vec3(lightInWorld(frames, light, l.position, l.frame))), 0));
        const glm::vec4 axis(l.spot.direction, 0.0f);
        return UniformValue::ofVector(
            glm::vec4(unit(glm::vec3(lightInWorld(frames, light, axis, l.frame))), 0.0f));
    }
    case Semantic::ReverseLightDirection: {
        // Towards the light from the world's origin: a directional light's L.
        const glm::vec4 world = lightInWorld(frames, light, l.position, l.frame);
        return UniformValue::ofVector(glm::vec4(unit(glm::vec3(world)), 0.0f));
    }
    case Semantic::CameraPositionWorld:
        return UniformValue::ofVector(glm::inverse(frames.view)[3]);
    case Semantic::AmbientProduct:
        return colour(l, l.colors.ia * m.ka);
    case Semantic::DiffuseProduct:
        return colour(l, l.colors.id * m.kd);
    case Semantic::SpecularProduct:
        return colour(l, l.colors.is * m.ks);
    case Semantic::AttenuationConstant:
        return UniformValue::ofNumber(l.attenuation.x);
    case Semantic::AttenuationLinear:
        return UniformValue::ofNumber(l.attenuation.y);
    case Semantic::AttenuationQuadratic:
        return UniformValue::ofNumber(l.attenuation.z);
    case Semantic::SpotDirectionEye:
        return UniformValue::ofVector(
            lightInEye(frames, light, glm::vec4(l.spot.direction, 0.0f), l.frame));
    case Semantic::HalfVectorEye: {
        // The fixed-function pipeline's state: the light's direction from the camera's origin
        // (its position, for a point light) plus the viewer's, far along +z.
        const glm::vec3 towards = unit(glm::vec3(lightInEye(frames, light, l.position, l.frame)));
        return UniformValue::ofVector(glm::vec4(unit(towards + glm::vec3(0.0f, 0.0f, 1.0f)), 0.0f));
    }
    }
    return {};
}

} // namespace lb
