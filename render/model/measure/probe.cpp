#include "probe.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <limits>
#include <optional>

namespace lb {

namespace {

struct Hit
{
    float t;
    glm::vec3 barycentric;
};

// Möller-Trumbore. `front` > 0 takes only triangles counter-clockwise as the ray sees them
// (front faces to GL), < 0 only clockwise ones, 0 both: as the renderer culls or not.
std::optional<Hit> intersect(const glm::vec3 &origin, const glm::vec3 &dir, const glm::vec3 &a,
                             const glm::vec3 &b, const glm::vec3 &c, float front)
{
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f || det * front < 0.0f)
        return std::nullopt;
    const float inv = 1.0f / det;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f)
        return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f)
        return std::nullopt;
    const float t = glm::dot(e2, q) * inv;
    if (t <= 0.0f)
        return std::nullopt;
    return Hit{t, glm::vec3(1.0f - u - v, u, v)};
}

// Where the ray meets the plane of triangle abc, as barycentric weights (outside the
// triangle too); nothing when the ray runs along the plane.
std::optional<glm::vec3> planeWeights(const glm::vec3 &origin, const glm::vec3 &dir,
                                      const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c)
{
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-20f)
        return std::nullopt;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) / det;
    const float v = glm::dot(dir, glm::cross(s, e1)) / det;
    return glm::vec3(1.0f - u - v, u, v);
}

// The ray through a point of the view, in GL window coordinates (origin bottom-left), in eye
// coordinates: its origin on the near plane and its direction to the far plane.
std::pair<glm::vec3, glm::vec3> eyeRay(const glm::mat4 &unproject, glm::vec2 window, QSize size)
{
    const float ndcX = 2.0f * window.x / float(size.width()) - 1.0f;
    const float ndcY = 2.0f * window.y / float(size.height()) - 1.0f;
    const glm::vec4 nearP = unproject * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    const glm::vec4 farP = unproject * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(nearP) / nearP.w;
    return {origin, glm::vec3(farP) / farP.w - origin};
}

template <typename T>
T interpolate(const std::vector<T> &values, const std::uint32_t *tri, const glm::vec3 &w)
{
    return w.x * values[tri[0]] + w.y * values[tri[1]] + w.z * values[tri[2]];
}

// GL's level of detail where the pixel containing `pixel` (top-left origin) shows triangle
// `tri`: the texture coordinate's change from the first pixel of the pixel's 2x2 quad to its
// neighbours in x and in y, as GPUs take derivatives (one level of detail per quad). The
// neighbours' coordinates are those of the triangle's plane, also where they lie outside it.
float levelOfDetail(const Frames &frames, const glm::vec3 (&corners)[3], const Mesh &mesh,
                    const std::uint32_t *tri, const Texture &texture, QSize size, QPointF pixel)
{
    const int x = int(std::floor(pixel.x()));
    const int y = size.height() - 1 - int(std::floor(pixel.y())); // GL rows count from below
    const glm::vec2 first(float(x & ~1) + 0.5f, float(y & ~1) + 0.5f);
    const glm::mat4 unproject = glm::inverse(frames.projection);
    glm::vec2 uv[3];
    const glm::vec2 steps[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    for (int k = 0; k < 3; ++k) {
        const auto [origin, dir] = eyeRay(unproject, first + steps[k], size);
        const auto w = planeWeights(origin, dir, corners[0], corners[1], corners[2]);
        if (!w)
            return 0.0f; // the plane seen edge-on: no pixel shows it anyway
        uv[k] = interpolate(mesh.uvs, tri, *w);
    }
    return texture.levelOfDetail(uv[1] - uv[0], uv[2] - uv[0]);
}

} // namespace

LightingInputs lightingInputs(const Scene &scene, const Frames &frames, int index)
{
    const Light &light = scene.lights[std::size_t(index)];
    LightingInputs in;
    in.lightEye = lightInEye(frames, index, light.position, light.frame);
    in.material = scene.objects[std::size_t(frames.object)].material;
    in.colors = light.colors;
    in.specular = scene.shading.specular;
    in.projection = scene.shading.projection;
    in.attenuation = light.attenuation;
    in.spotDirectionEye = spotDirectionInEye(frames, index, light);
    in.spotCosCutoff = spotCosCutoff(light.spot);
    in.spotExponent = light.spot.exponent;
    return in;
}

ProbeResult probePixel(const Scene &scene, const ProbedObjects &objects, QSize size, QPoint pixel)
{
    ProbeResult r;
    if (size.isEmpty())
        return r;
    const float aspect = float(size.width()) / float(size.height());
    const Frames view = computeFrames(scene, aspect);

    // The pixel centre on the near and far planes, back through the projection.
    const auto [origin, dir] =
        eyeRay(glm::inverse(view.projection),
               glm::vec2(float(pixel.x()) + 0.5f, float(size.height() - pixel.y()) - 0.5f), size);

    // Eye space is shared by every object: the nearest hit over all of them is the one drawn.
    float nearest = std::numeric_limits<float>::max();
    std::vector<glm::vec3> eyePositions;
    const int count = std::min(int(objects.size()), int(scene.objects.size()));
    for (int o = 0; o < count; ++o) {
        const Mesh *mesh = objects[std::size_t(o)].mesh;
        const ObjectSettings &object = scene.objects[std::size_t(o)];
        if (!mesh || !object.visible)
            continue;
        const Frames frames = computeFrames(scene, aspect, o);
        eyePositions.resize(mesh->vertexCount());
        for (std::size_t i = 0; i < mesh->vertexCount(); ++i)
            eyePositions[i] = glm::vec3(frames.modelView * glm::vec4(mesh->positions[i], 1.0f));
        const float front = !object.culls() ? 0.0f : mirrors(frames) ? -1.0f : 1.0f;
        for (std::size_t tri = 0; tri < mesh->triangleCount(); ++tri) {
            const std::uint32_t *idx = &mesh->indices[tri * 3];
            const auto hit = intersect(origin, dir, eyePositions[idx[0]], eyePositions[idx[1]],
                                       eyePositions[idx[2]], front);
            if (hit && hit->t < nearest) {
                nearest = hit->t;
                r.hit = true;
                r.object = o;
                r.triangle = tri;
                r.barycentric = hit->barycentric;
            }
        }
    }
    if (!r.hit)
        return r;
    static const Texture checker;
    const ProbedObject &hit = objects[std::size_t(r.object)];
    return probeSurface(scene, r.object, *hit.mesh, hit.texture ? *hit.texture : checker, size,
                        r.triangle, r.barycentric);
}

ProbeResult probeSurface(const Scene &scene, int object, const Mesh &mesh, const Texture &texture,
                         QSize size, std::size_t triangle, const glm::vec3 &barycentric)
{
    ProbeResult r;
    if (size.isEmpty() || triangle >= mesh.triangleCount() || object < 0 ||
        object >= int(scene.objects.size()))
        return r;
    r.hit = true;
    r.object = object;
    r.triangle = triangle;
    r.barycentric = barycentric;
    const ObjectSettings &settings = scene.objects[std::size_t(object)];
    const Frames frames = computeFrames(scene, float(size.width()) / float(size.height()), object);
    const std::uint32_t *tri = &mesh.indices[r.triangle * 3];
    // The triangle's corners in eye coordinates.
    glm::vec3 corners[3];
    for (int k = 0; k < 3; ++k)
        corners[k] = glm::vec3(frames.modelView * glm::vec4(mesh.positions[tri[k]], 1.0f));
    const glm::vec3 &w = r.barycentric;
    const glm::mat3 normals(frames.normals);
    auto eyeNormal = [&](const glm::vec3 &n) { return normals * n; };

    r.position = w.x * corners[0] + w.y * corners[1] + w.z * corners[2];
    r.normal = glm::normalize(eyeNormal(interpolate(mesh.normals, tri, w)));
    // A mesh without colours reads white, one without texture coordinates (0, 0): the
    // constant attribute values the renderer gives the GPU.
    if (scene.shading.vertexColors && !mesh.colors.empty())
        r.base *= interpolate(mesh.colors, tri, w);
    const glm::vec2 pixel = pixelOf(frames, r.position, float(size.width()), float(size.height()));
    r.pixel = QPointF(pixel.x, pixel.y);
    if (!mesh.uvs.empty()) {
        r.uv = interpolate(mesh.uvs, tri, w);
        r.lod = levelOfDetail(frames, corners, mesh, tri, texture, size, r.pixel);
    }
    if (settings.texture)
        r.base *= texture.sample(r.uv, settings.sampling, r.lod);

    for (int i = 0; i < kMaxLights; ++i) {
        if (!scene.lights[std::size_t(i)].enabled)
            continue;
        ProbeLight light{i, lightingInputs(scene, frames, i), {}};
        light.terms = evaluateLighting(r.position, r.normal, light.inputs);
        r.total.add(light.terms, scene.shading.terms);
        r.lights.push_back(light);
    }

    // The per-vertex shadings weight the model at the corners: Gouraud by the point's
    // barycentric weights, flat all on the provoking vertex (GL's default, the last one), so
    // one colour per triangle; the base colour varies over the triangle in both.
    const glm::vec3 weights =
        scene.shading.shading == Shading::Flat ? glm::vec3(0.0f, 0.0f, 1.0f) : w;
    const auto atCorner = [&](int k, const LightingInputs &in) {
        return evaluateLighting(corners[k], eyeNormal(mesh.normals[tri[k]]), in);
    };
    // The Show choice: light 1's vectors and numbers, on or off, at the point (Phong) or at
    // the corners, weighted (Gouraud, flat), as the built-in programs compute them.
    const ShowChoice show = scene.shading.show;
    const bool phong = scene.shading.shading == Shading::Phong;
    const LightingInputs light1 = lightingInputs(scene, frames, 0);
    glm::vec3 colour(0.0f);
    if (show != ShowChoice::Colour && phong) {
        colour = shownColor(show, evaluateLighting(r.position, r.normal, light1));
    } else if (show != ShowChoice::Colour) {
        for (int k = 0; k < 3; ++k)
            colour += weights[k] * shownColor(show, atCorner(k, light1));
    } else if (!scene.shading.lighting) {
        colour = unlitColor(settings.material, r.base);
    } else if (phong) {
        colour = shadedColor(r.total.ambient + r.total.diffuse, r.total.specular, r.base);
    } else {
        glm::vec3 ambientDiffuse(0.0f), specular(0.0f);
        for (int k = 0; k < 3; ++k) {
            LightingSum v;
            for (const ProbeLight &light : r.lights)
                v.add(atCorner(k, light.inputs), scene.shading.terms);
            ambientDiffuse += weights[k] * (v.ambient + v.diffuse);
            specular += weights[k] * v.specular;
        }
        colour = shadedColor(ambientDiffuse, specular, r.base);
    }
    r.reference = glm::clamp(colour, 0.0f, 1.0f);
    return r;
}

ProbeResult probeFramePixel(const Scene &scene, const ProbedObjects &objects, QSize frame,
                            QPoint pixel, PixelView *view)
{
    const PixelView v = viewOfPixel(scene, frame, pixel);
    if (view)
        *view = v;
    return probePixel(sceneOfSide(scene, v.sideB), objects, v.size, v.pixel);
}

} // namespace lb
