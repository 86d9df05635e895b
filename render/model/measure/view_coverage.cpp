#include "view_coverage.h"

#include "frames.h"

#include <QCoreApplication>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>

namespace lb {

namespace {

struct ViewCoverageMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::ViewCoverage)
};

// The axis along which the mesh has no extent (0, 1, 2), or -1 when it is not flat.
int flatAxis(const Mesh &mesh)
{
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3 &p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 extent = hi - lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    for (int axis = 0; axis < 3; ++axis)
        if (extent[axis] <= 1e-5f * largest)
            return axis;
    return -1;
}

} // namespace

QString viewProblem(const Scene &scene, int index, const Mesh &mesh, QSize size)
{
    if (index < 0 || index >= int(scene.objects.size()) || size.isEmpty())
        return {};
    const ObjectSettings &object = scene.objects[std::size_t(index)];
    if (!object.visible || mesh.triangleCount() == 0)
        return {};
    const Frames frames = computeFrames(scene, float(size.width()) / float(size.height()), index);
    const glm::mat4 clip = frames.projection * frames.modelView;
    const float front = !object.culls() ? 0.0f : mirrors(frames) ? -1.0f : 1.0f;
    const double pixelArea = 0.25 * double(size.width()) * double(size.height()); // per NDC unit²
    bool inView = false, facing = false;
    double covered = 0.0, behind = 0.0; // pixels of front faces, of back faces
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        std::array<glm::vec3, 3> ndc;
        bool nearEye = false;
        for (int k = 0; k < 3; ++k) {
            const glm::vec4 c = clip * glm::vec4(mesh.positions[mesh.indices[3 * t + k]], 1.0f);
            nearEye = nearEye || !(c.w > 0.0f);
            ndc[std::size_t(k)] = glm::vec3(c) / c.w;
        }
        if (nearEye)
            continue; // near the eye or behind it: not worth clipping for a "why"
        const glm::vec3 lo = glm::min(ndc[0], glm::min(ndc[1], ndc[2]));
        const glm::vec3 hi = glm::max(ndc[0], glm::max(ndc[1], ndc[2]));
        if (hi.x < -1.0f || lo.x > 1.0f || hi.y < -1.0f || lo.y > 1.0f || hi.z < -1.0f ||
            lo.z > 1.0f)
            continue;
        inView = true;
        const glm::vec2 e1 = glm::vec2(ndc[1] - ndc[0]), e2 = glm::vec2(ndc[2] - ndc[0]);
        const float twice = e1.x * e2.y - e1.y * e2.x; // > 0: counter-clockwise on screen
        const double pixels = 0.5 * std::abs(double(twice)) * pixelArea;
        // Front faces wind counter-clockwise on screen (clockwise in a mirrored frame).
        const bool frontFacing = twice * (mirrors(frames) ? -1.0f : 1.0f) > 0.0f;
        if (!frontFacing) {
            behind += pixels;
            if (front != 0.0f)
                continue; // culled
        }
        facing = true;
        covered += frontFacing ? pixels : 0.0;
        if (covered >= 1.0)
            return {};
    }
    if (behind >= 1.0 && object.faces != Faces::TwoSided) {
        if (front != 0.0f)
            return ViewCoverageMessages::tr(
                "draws nothing in view: every face in view turns its back to the camera, and "
                "back faces are culled");
        return ViewCoverageMessages::tr(
            "is seen from behind: every face in view turns its back to the camera, lit as "
            "from behind (dark); Faces: Both sides lit shows that side lit");
    }
    if (behind + covered >= 1.0)
        return {};
    if (!inView)
        return ViewCoverageMessages::tr("draws nothing in view: it lies outside the view");
    if (!facing)
        return ViewCoverageMessages::tr("draws nothing in view: every face in view turns away "
                                        "from the camera and back faces are culled");
    static const char *const planes[] = {"YZ", "XZ", "XY"};
    if (const int axis = flatAxis(mesh); axis >= 0)
        //: %1: the plane the mesh lies in (YZ, XZ, XY)
        return ViewCoverageMessages::tr("draws nothing in view: it is flat (in the %1 plane) and "
                                        "seen edge-on: turn it or the camera")
            .arg(QLatin1String(planes[axis]));
    return ViewCoverageMessages::tr("draws nothing in view: it covers less than a pixel");
}

} // namespace lb
