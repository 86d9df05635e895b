#include "frames.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
// Light `index`'s place in Frames' per-light arrays (a bad index reads light 1's).
std::size_t lightSlot(int index)
{
    return std::size_t(std::clamp(index, 0, kMaxLights - 1));
}
} // namespace

glm::mat4 modelMatrix(const ObjectSettings &object)
{
    const glm::vec3 r = glm::radians(object.rotationDegrees);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), object.translation);
    m = glm::rotate(m, r.z, glm::vec3(0, 0, 1));
    m = glm::rotate(m, r.y, glm::vec3(0, 1, 0));
    m = glm::rotate(m, r.x, glm::vec3(1, 0, 0));
    return glm::scale(m, object.scale);
}

glm::mat4 normalMatrix(const glm::mat4 &m)
{
    return glm::inverseTranspose(m);
}

Frames computeFrames(const Scene &scene, float aspect, int object)
{
    Frames f;
    const int last = int(scene.objects.size()) - 1;
    f.object = std::clamp(object, 0, last);
    f.view = scene.camera.view();
    const auto normalsOf = [&](const glm::mat4 &modelView) {
        return scene.shading.normalsByModelView ? modelView : normalMatrix(modelView);
    };
    f.model = modelMatrix(scene.objects[std::size_t(f.object)]);
    f.modelView = f.view * f.model;
    f.normals = normalsOf(f.modelView);
    f.viewNormals = normalMatrix(f.view);
    f.projection = scene.camera.projection(aspect, scene.shading.projection);
    for (std::size_t i = 0; i < f.lightModelView.size(); ++i) {
        const int attached = std::clamp(scene.lights[i].object, 0, last);
        if (attached == f.object) {
            f.lightModelView[i] = f.modelView;
            f.lightNormals[i] = f.normals;
        } else {
            f.lightModelView[i] = f.view * modelMatrix(scene.objects[std::size_t(attached)]);
            f.lightNormals[i] = normalsOf(f.lightModelView[i]);
        }
    }
    return f;
}

bool mirrors(const Frames &frames)
{
    return glm::determinant(glm::mat3(frames.modelView)) < 0.0f;
}

glm::vec4 lightInEye(const Frames &frames, int index, const glm::vec4 &light, LightFrame frame)
{
    const bool directional = light.w == 0.0f;
    const std::size_t i = lightSlot(index);
    glm::vec4 eye = light;
    switch (frame) {
    case LightFrame::Camera:
        break;
    case LightFrame::World:
        eye = directional ? frames.viewNormals * light : frames.view * light;
        break;
    case LightFrame::Object:
        eye = directional ? frames.lightNormals[i] * light : frames.lightModelView[i] * light;
        break;
    }
    // The inverse transpose of an affine matrix puts a translation term into w; a direction
    // keeps w = 0 and a point w = 1 (the matrices here are affine).
    eye.w = light.w;
    return eye;
}

glm::vec4 lightForDrawnObject(const Frames &frames, int index, const glm::vec4 &light,
                              LightFrame frame)
{
    const std::size_t i = lightSlot(index);
    if (frame != LightFrame::Object || frames.lightModelView[i] == frames.modelView)
        return light;
    // Into eye coordinates through the attached object, and back through the drawn one.
    const bool directional = light.w == 0.0f;
    glm::vec4 back = glm::inverse(directional ? frames.normals : frames.modelView) *
                     lightInEye(frames, index, light, frame);
    back.w = light.w;
    return back;
}

glm::vec3 spotDirectionInEye(const Frames &frames, int index, const Light &light)
{
    // normalize(), as the shaders write it; a direction of length 0 is refused on the way in.
    return glm::normalize(
        glm::vec3(lightInEye(frames, index, glm::vec4(light.spot.direction, 0.0f), light.frame)));
}

float spotCosCutoff(const Spot &spot)
{
    return spot.cutoffDegrees >= 180.0f ? -1.0f : std::cos(glm::radians(spot.cutoffDegrees));
}

glm::vec4 eyeToFrame(const Frames &frames, int index, const glm::vec4 &eye, LightFrame frame)
{
    if (frame == LightFrame::Camera)
        return eye;
    const std::size_t i = lightSlot(index);
    const bool directional = eye.w == 0.0f;
    const bool world = frame == LightFrame::World;
    const glm::mat4 &there = directional ? (world ? frames.viewNormals : frames.lightNormals[i])
                                         : (world ? frames.view : frames.lightModelView[i]);
    glm::vec4 back = glm::inverse(there) * eye;
    back.w = eye.w;
    return back;
}

glm::vec2 pixelOf(const Frames &frames, const glm::vec3 &eye, float width, float height)
{
    const glm::vec4 clip = frames.projection * glm::vec4(eye, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x + 1.0f) * 0.5f * width, (1.0f - ndc.y) * 0.5f * height);
}

} // namespace lb
