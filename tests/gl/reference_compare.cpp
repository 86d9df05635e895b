#include "reference_compare.h"

#include <QDir>
#include <QRegularExpression>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb::test {

int channelDifference(QRgb gpu, const glm::vec3 &reference)
{
    const int r = int(std::lround(reference.r * 255)), g = int(std::lround(reference.g * 255)),
              b = int(std::lround(reference.b * 255));
    return std::max({std::abs(qRed(gpu) - r), std::abs(qGreen(gpu) - g), std::abs(qBlue(gpu) - b)});
}

QPoint brightestGreen(const QImage &frame)
{
    QPoint peak;
    int best = -1;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            if (const int v = qGreen(frame.pixel(x, y)); v > best) {
                best = v;
                peak = QPoint(x, y);
            }
    return peak;
}

int largestDifference(const QImage &a, const QImage &b)
{
    int worst = 0;
    for (int y = 0; y < std::min(a.height(), b.height()); ++y)
        for (int x = 0; x < std::min(a.width(), b.width()); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q))});
        }
    return worst;
}

namespace {

// Whether each light's spot cone has both points inside or both outside: its edge is a step
// in brightness, where a rounding difference may rightly put a pixel on the other side.
bool sameSideOfEveryCone(const ProbeResult &a, const ProbeResult &b)
{
    if (a.lights.size() != b.lights.size())
        return false;
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        if ((a.lights[i].terms.spot > 0.0f) != (b.lights[i].terms.spot > 0.0f))
            return false;
    return true;
}

// Whether the texture lookup at `p` sits by a step: the nearest filter's texel edges and
// the nearest-mipmap level switches are steps in colour, where the GPU's coordinate (or level
// of detail) and the probe's, a rounding apart, may rightly fall on different sides.
bool byATextureStep(const ProbeResult &p, const ObjectSettings &object, const Texture &texture)
{
    if (!object.texture || object.sampling.filter != TextureFilter::Nearest)
        return false;
    const Texture::Levels levels = texture.levelsAt(p.lod, object.sampling);
    if (object.sampling.mipmaps && p.lod > 0.0f) {
        const float toSwitch = std::abs(p.lod - 0.5f - std::round(p.lod - 0.5f));
        if (toSwitch < 0.05f)
            return true;
    }
    for (const int level : {levels.first, levels.second}) {
        const QImage &image = texture.level(level);
        const glm::vec2 texels = p.uv * glm::vec2(float(image.width()), float(image.height()));
        for (const float t : {texels.x, texels.y})
            if (std::abs(t - std::round(t)) < 0.02f)
                return true;
    }
    return false;
}

} // namespace

Comparison compareWithReference(OffscreenRenderer &offscreen, const Scene &scene,
                                const QImage &frame, int step)
{
    step *= kGridCoarsening;
    const ProbedObjects objects = offscreen.probedObjects(scene);
    const QSize size = frame.size();
    // A compared frame may show two sides; the divider between them is no surface.
    const int divider = dividerColumn(scene, size);
    auto probe = [&](QPoint pixel) { return probeFramePixel(scene, objects, size, pixel); };
    const bool flat =
        scene.shading.shading == Shading::Flat ||
        (scene.compare.mode != CompareMode::Off && scene.compare.shading == Shading::Flat);
    Comparison c;
    for (int y = 3; y < size.height() - 3; y += step) {
        for (int x = 3; x < size.width() - 3; x += step) {
            if (divider >= 0 && std::abs(x - divider) <= 3)
                continue;
            const ProbeResult p = probe(QPoint(x, y));
            if (!p.hit)
                continue;
            bool interior = true;
            for (const QPoint d : {QPoint(2, 0), QPoint(-2, 0), QPoint(0, 2), QPoint(0, -2)}) {
                const ProbeResult n = probe(QPoint(x, y) + d);
                // Flat shading steps from triangle to triangle: an edge is like a crease.
                interior = interior && n.hit && n.object == p.object &&
                           glm::dot(n.normal, p.normal) > 0.98f && sameSideOfEveryCone(n, p) &&
                           (!flat || n.triangle == p.triangle);
            }
            static const Texture checker;
            const Texture *texture = objects[std::size_t(p.object)].texture;
            if (!interior || byATextureStep(p, scene.objects[std::size_t(p.object)],
                                            texture ? *texture : checker))
                continue;
            ++c.compared;
            if (p.total.specular.r > 0.05f)
                ++c.withSpecular;
            const int diff = channelDifference(frame.pixel(x, y), p.reference);
            if (diff > c.worst) {
                c.worst = diff;
                c.worstAt = QPoint(x, y);
                const QRgb g = frame.pixel(x, y);
                c.worstText = QString("gpu (%1,%2,%3) reference (%4,%5,%6)")
                                  .arg(qRed(g))
                                  .arg(qGreen(g))
                                  .arg(qBlue(g))
                                  .arg(p.reference.r * 255)
                                  .arg(p.reference.g * 255)
                                  .arg(p.reference.b * 255);
            }
        }
    }
    return c;
}

QString saveForInspection(const QImage &frame, const QString &name)
{
    const QDir folder(QStringLiteral(LB_TEST_OUTPUT)); // CMake's build/tests/test-output
    folder.mkpath(".");
    QString file = name;
    file.replace(QRegularExpression("[^A-Za-z0-9_-]+"), "_");
    const QString path = folder.absoluteFilePath(file + ".png");
    frame.save(path);
    return path;
}

QString checkAgainstReference(OffscreenRenderer &offscreen, const Scene &scene, const QString &name,
                              int minCompared, int minSpecular, int tolerance)
{
    const QImage frame = offscreen.render(scene);
    const Comparison c = compareWithReference(offscreen, scene, frame);
    qInfo("%s: %d pixels compared (%d with a highlight), worst %d/255", qPrintable(name),
          c.compared, c.withSpecular, c.worst);
    if (c.compared < ofThisGrid(minCompared))
        return QString("only %1 pixels compared").arg(c.compared);
    if (c.withSpecular < ofThisGrid(minSpecular))
        return QString("only %1 pixels with a highlight").arg(c.withSpecular);
    if (c.worst <= tolerance)
        return {};
    return QString("pixel (%1, %2) is off by %3/255: %4; frame in %5")
        .arg(c.worstAt.x())
        .arg(c.worstAt.y())
        .arg(c.worst)
        .arg(c.worstText, saveForInspection(frame, name));
}

Scene testScene()
{
    Scene s;
    s.showLight = false;
    s.objects[0].tessellation = 24;
    s.objects[0].rotationDegrees = {20, 30, 0};
    s.objects[0].scale = {1.2f, 0.8f, 1.0f};
    s.camera.distance = 3.8f; // the object fills most of the small frame
    return s;
}

} // namespace lb::test
