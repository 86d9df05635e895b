#pragma once
// The matrices of each frame, named as in the slides, and the light brought into eye space.
// The renderer uploads exactly these; the probe and the tests use the same ones.

#include "scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace lb {

// The matrices of one drawn object (Scene::objects[object]) in one view.
struct Frames
{
    int object = 0;
    glm::mat4 model{1.0f};
    glm::mat4 view{1.0f};        // mView: world -> camera (lookAt)
    glm::mat4 modelView{1.0f};   // mModelView = mView * model
    glm::mat4 normals{1.0f};     // mNormals = inverse transpose of mModelView
    glm::mat4 viewNormals{1.0f}; // mViewNormals = inverse transpose of mView
    glm::mat4 projection{1.0f};  // mProjection
    // Each light's object frame: the model-view and normal matrix of the object it is
    // attached to (Light::object), which need not be the one drawn.
    std::array<glm::mat4, kMaxLights> lightModelView, lightNormals;
};

// Object transform: scale first, then rotate about X, then Y, then Z, then translate.
glm::mat4 modelMatrix(const ObjectSettings &object);
// The matrix that carries normals (and directions) alongside points moved by `m`.
glm::mat4 normalMatrix(const glm::mat4 &m);
// The frames of scene.objects[object] (clamped to the list) in a view of `aspect`.
Frames computeFrames(const Scene &scene, float aspect, int object = 0);

// Whether the model-view mirrors (a negative scale): the mesh's counter-clockwise faces then
// reach the screen clockwise, and back-face culling must keep the clockwise ones.
bool mirrors(const Frames &frames);

// Light `index`'s position (or any point or direction given in its frame) in eye
// coordinates, as the slides' variants I, II and III compute it: camera: as given; world:
// mView for a point, mViewNormals for a direction; object: the attached object's mModelView
// for a point, its mNormals for a direction. The result keeps w.
glm::vec4 lightInEye(const Frames &frames, int index, const glm::vec4 &light, LightFrame frame);
// The same point or direction as a shader drawing frames.object must be given it to find it
// through its own matrices: as given, unless the light is in the frame of another object,
// where it is carried into the drawn object's frame. (Shaders that transform the light
// themselves, the slides' variant III, then light every object as the panel says.)
glm::vec4 lightForDrawnObject(const Frames &frames, int index, const glm::vec4 &light,
                              LightFrame frame);
// The spotlight's axis in eye coordinates, unit length: its direction in the light's frame,
// carried as lightInEye() carries a direction (w = 0).
glm::vec3 spotDirectionInEye(const Frames &frames, int index, const Light &light);
// cos(cutoff) as the shaders get it; exactly -1 for 180 degrees (no spot).
float spotCosCutoff(const Spot &spot);
// The way back: a point (w = 1) or direction (w = 0) in eye coordinates, in `frame`'s
// coordinates, such that lightInEye() of the result gives `eye` again.
glm::vec4 eyeToFrame(const Frames &frames, int index, const glm::vec4 &eye, LightFrame frame);

// Where an eye-space point lands in a view `width` x `height` pixels, top-left origin.
glm::vec2 pixelOf(const Frames &frames, const glm::vec3 &eye, float width, float height);

} // namespace lb
