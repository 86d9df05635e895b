#pragma once
// The probe: which surface point a pixel shows, and what the lighting model says that pixel
// must be. A ray through the pixel's centre finds the triangle; its barycentric weights are
// the perspective-correct ones, so Gouraud's interpolation can be repeated on the CPU.

#include "compare.h"
#include "frames.h"
#include "lighting.h"
#include "mesh.h"
#include "scene.h"
#include "texture.h"

#include <QPointF>
#include <QSize>

namespace lb {

// One enabled light's part in a probed point.
struct ProbeLight
{
    int index = 0; // 0 for light 1
    LightingInputs inputs;
    LightingTerms terms; // the model at the point for this light (the Phong-shading view)
};

struct ProbeResult
{
    bool hit = false;
    int object = 0; // which of the scene's objects (0 for the first)
    std::size_t triangle = 0;
    glm::vec3 barycentric{0.0f};
    glm::vec3 position{0.0f};       // eye coordinates
    glm::vec3 normal{0.0f};         // unit, eye coordinates
    std::vector<ProbeLight> lights; // each enabled light's vectors and terms
    LightingSum total;              // their sum at this point (the Phong-shading view)
    glm::vec3 base{1.0f};           // vertex colour x texture, white where switched off
    // The texture coordinate at the point and GL's level of detail there (log2 of the texels
    // one pixel step crosses, from the pixel's 2x2 quad, as the GPU takes it).
    glm::vec2 uv{0.0f};
    float lod = 0.0f;
    glm::vec3 reference{0.0f}; // the pixel in the active shading mode, clamped to [0, 1]
    QPointF pixel;             // where the point lies in the view, top-left origin
};

// What the probe knows of one of the scene's objects: the mesh drawn and the texture the
// texture switch puts on it. An object without a mesh (still loading) is not hit.
struct ProbedObject
{
    const Mesh *mesh = nullptr;
    const Texture *texture = nullptr;
};
// By index into Scene::objects; missing entries count as objects without a mesh.
using ProbedObjects = std::vector<ProbedObject>;

// The model's inputs for light `index`, brought into eye coordinates, for the object whose
// frames these are (its material).
LightingInputs lightingInputs(const Scene &scene, const Frames &frames, int index);

// `pixel` is in framebuffer pixels from the top-left corner; (x + 0.5, y + 0.5) is the centre
// GL samples. The frame is `size` pixels large. The nearest visible object's surface wins.
ProbeResult probePixel(const Scene &scene, const ProbedObjects &objects, QSize size, QPoint pixel);

// The model at a known surface point (an object, a triangle of its mesh and barycentric
// weights), seen in a view `size` pixels large: how the probe follows its point while the
// camera and lights move.
ProbeResult probeSurface(const Scene &scene, int object, const Mesh &mesh, const Texture &texture,
                         QSize size, std::size_t triangle, const glm::vec3 &barycentric);

// The same for a pixel of a whole frame that may show two sides of a comparison: the side
// the pixel shows, probed in that side's own view (the difference view probes side A).
// `view` (optional) receives which side and where.
ProbeResult probeFramePixel(const Scene &scene, const ProbedObjects &objects, QSize frame,
                            QPoint pixel, PixelView *view = nullptr);

} // namespace lb
