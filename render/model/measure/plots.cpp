#include "plots.h"

#include "frames.h"
#include "lighting.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

constexpr glm::vec3 kNormal{0.0f, 0.0f, 1.0f};

// A unit vector in the x-z plane at `degrees` from +z towards +x.
glm::vec3 inPlane(float degrees)
{
    const float a = glm::radians(degrees);
    return {std::sin(a), 0.0f, std::cos(a)};
}

float sampleAt(int i, int samples, float from, float to)
{
    return from + (to - from) * float(i) / float(samples - 1);
}

float mean(const glm::vec3 &c)
{
    return (c.r + c.g + c.b) / 3.0f;
}

// The material, lights and frames the plots describe: the probed object's where a point is
// probed, else the selected object's.
struct PlotSubject
{
    const ProbeResult *probe = nullptr; // null unless it hit
    int object = 0;
    Frames frames;
    std::vector<int> lights; // the enabled ones
    // The object's origin in eye coordinates: its centre, where no point is probed.
    glm::vec3 centre() const { return glm::vec3(frames.modelView * glm::vec4(0, 0, 0, 1)); }
};

PlotSubject subjectOf(const Scene &scene, const ProbeResult *probe)
{
    PlotSubject s;
    s.probe = probe && probe->hit ? probe : nullptr;
    s.object = s.probe ? s.probe->object : scene.selected;
    s.object = std::clamp(s.object, 0, int(scene.objects.size()) - 1);
    s.frames = computeFrames(scene, 1.0f, s.object);
    for (int i = 0; i < kMaxLights; ++i)
        if (scene.lights[std::size_t(i)].enabled)
            s.lights.push_back(i);
    return s;
}

const ProbeLight *probedLight(const PlotSubject &s, int light)
{
    if (!s.probe)
        return nullptr;
    for (const ProbeLight &l : s.probe->lights)
        if (l.index == light)
            return &l;
    return nullptr;
}

QString lightKey(int light)
{
    return QStringLiteral("light%1").arg(light + 1);
}

// A directional light straight along N: what the specular and diffuse curves sweep against.
LightingInputs sweepInputs(const Scene &scene, const PlotSubject &s)
{
    LightingInputs in;
    in.lightEye = glm::vec4(kNormal, 0.0f);
    in.material = scene.objects[std::size_t(s.object)].material;
    in.specular = scene.shading.specular;
    return in;
}

Plot specularPlot(const Scene &scene, const PlotSubject &s, int samples)
{
    Plot plot;
    // To 180: Blinn-Phong's highlight does not end 90 degrees from R, and a probed point's
    // 2·acos(N·H) can lie beyond 90.
    plot.xMax = 180.0f;
    LightingInputs in = sweepInputs(scene, s);
    plot.shininess = in.material.shininess;
    // L = N, so R = N and the angle of V from the mirror direction is its angle from N. Each
    // model's curves, as its row lists them (lighting_models.h).
    for (const SpecularModelRow &model : specularModels())
        for (const SpecularPlotCurve &c : model.curves) {
            PlotSeries series{
                QString::fromLatin1(c.key), PlotRole::Specular, -1, glm::vec3(1.0f), c.dashed, {}};
            LightingInputs swept = in;
            swept.specular = model.model;
            swept.material.shininess = plot.shininess * c.exponentTimes;
            for (int i = 0; i < samples; ++i) {
                const float angle = sampleAt(i, samples, plot.xMin, plot.xMax);
                const LightingTerms t =
                    lightingTerms(kNormal, kNormal, inPlane(angle), 0.0f, swept);
                series.points.push_back({angle, t.specularFactor});
            }
            plot.series.push_back(std::move(series));
        }
    // Each probed light's own angle, in the model the probe used (side B's in a compare view),
    // on that model's first curve at the in-plane angle that gives its cosine (the row's
    // planeDegrees). None where the light is behind the surface or the cosine has no place.
    for (int light : s.lights) {
        const ProbeLight *p = probedLight(s, light);
        if (!p || p->terms.nDotL < 0.0f)
            continue;
        const SpecularModelRow &model = specularModel(p->inputs.specular);
        const std::optional<float> angle = model.planeDegrees(p->terms.specularAngle);
        const auto series =
            std::find_if(plot.series.begin(), plot.series.end(), [&](const PlotSeries &ps) {
                return specularModelOfCurve(ps.key) == &model;
            });
        if (!angle || series == plot.series.end())
            continue;
        plot.markers.push_back({int(series - plot.series.begin()),
                                light,
                                p->inputs.colors.id,
                                {*angle, p->terms.specularFactor}});
    }
    return plot;
}

Plot diffusePlot(const Scene &scene, const PlotSubject &s, int samples)
{
    Plot plot;
    plot.xMax = 180.0f;
    const LightingInputs in = sweepInputs(scene, s);
    PlotSeries series{QStringLiteral("diffuse"), PlotRole::Diffuse, -1, glm::vec3(1.0f), false, {}};
    for (int i = 0; i < samples; ++i) {
        const float angle = sampleAt(i, samples, plot.xMin, plot.xMax);
        const LightingTerms t = lightingTerms(inPlane(angle), kNormal, kNormal, 0.0f, in);
        series.points.push_back({angle, diffuseFactor(t.nDotL)});
    }
    plot.series.push_back(std::move(series));
    for (int light : s.lights)
        if (const ProbeLight *p = probedLight(s, light))
            plot.markers.push_back(
                {0,
                 light,
                 p->inputs.colors.id,
                 {degreesFromCosine(p->terms.nDotL), diffuseFactor(p->terms.nDotL)}});
    return plot;
}

Plot attenuationPlot(const Scene &scene, const PlotSubject &s, int samples)
{
    Plot plot;
    // Far enough to show the probed distances and the lights' distances to the object's
    // centre half again, and at least 5 units.
    float far = 5.0f;
    const glm::vec3 centre = s.centre();
    std::vector<int> pointLights;
    for (int light : s.lights) {
        const LightingInputs in = lightingInputs(scene, s.frames, light);
        if (in.lightEye.w == 0.0f)
            continue;
        pointLights.push_back(light);
        far = std::max(far, 1.5f * glm::length(glm::vec3(in.lightEye) - centre));
        if (const ProbeLight *p = probedLight(s, light))
            far = std::max(far, 1.5f * p->terms.distance);
    }
    plot.xMax = std::ceil(far);
    if (pointLights.empty())
        plot.gap = PlotGap::NoPointLight;
    for (int light : pointLights) {
        const Light &l = scene.lights[std::size_t(light)];
        PlotSeries series{lightKey(light), PlotRole::Light, light, l.colors.id, false, {}};
        for (int i = 0; i < samples; ++i) {
            const float d = sampleAt(i, samples, plot.xMin, plot.xMax);
            series.points.push_back({d, attenuationFactor(l.position, d, l.attenuation)});
        }
        if (const ProbeLight *p = probedLight(s, light))
            plot.markers.push_back({int(plot.series.size()),
                                    light,
                                    p->inputs.colors.id,
                                    {p->terms.distance, p->terms.attenuation}});
        plot.series.push_back(std::move(series));
    }
    return plot;
}

Plot spotPlot(const Scene &scene, const PlotSubject &s, int samples)
{
    Plot plot;
    std::vector<int> spots;
    for (int light : s.lights)
        if (spotCosCutoff(scene.lights[std::size_t(light)].spot) > -1.0f)
            spots.push_back(light);
    if (spots.empty())
        plot.gap = PlotGap::NoSpotlight;
    float widest = 0.0f;
    for (int light : spots)
        widest = std::max(widest, scene.lights[std::size_t(light)].spot.cutoffDegrees);
    // A cone under 80 degrees on 0 to 90, unless a probed point lies further out.
    const auto probedAngle = [&](int light) -> std::optional<float> {
        if (const ProbeLight *p = probedLight(s, light))
            return degreesFromCosine(
                glm::dot(-p->terms.L, glm::normalize(p->inputs.spotDirectionEye)));
        return std::nullopt;
    };
    bool beyond = false;
    for (int light : spots)
        beyond = beyond || probedAngle(light).value_or(0.0f) > 90.0f;
    plot.xMax = widest < 80.0f && !beyond ? 90.0f : 180.0f;
    // The axis D = -z; L at `angle` from it, seen from the lit point (towards the light).
    const glm::vec3 axis{0.0f, 0.0f, -1.0f};
    for (int light : spots) {
        const Light &l = scene.lights[std::size_t(light)];
        const Spot &spot = l.spot;
        PlotSeries series{lightKey(light), PlotRole::Light, light, l.colors.id, false, {}};
        for (int i = 0; i < samples; ++i) {
            const float angle = sampleAt(i, samples, plot.xMin, plot.xMax);
            const glm::vec3 swept = inPlane(angle);
            const glm::vec3 towardsPoint{swept.x, 0.0f, -swept.z};
            series.points.push_back(
                {angle, spotFactor(-towardsPoint, axis, spotCosCutoff(spot), spot.exponent)});
        }
        if (const std::optional<float> x = probedAngle(light))
            plot.markers.push_back({int(plot.series.size()),
                                    light,
                                    l.colors.id,
                                    {*x, probedLight(s, light)->terms.spot}});
        plot.series.push_back(std::move(series));
    }
    return plot;
}

Plot lobePlot(const Scene &scene, const PlotSubject &s, int samples)
{
    Plot plot;
    plot.polar = true;
    plot.xMin = -90.0f;
    plot.xMax = 90.0f;
    if (s.lights.empty()) {
        plot.gap = PlotGap::NoLight;
        return plot;
    }
    // The first light on; at the probed point, or where the object's centre faces the camera.
    const int light = s.lights.front();
    plot.lobeLight = light;
    LightingInputs in;
    glm::vec3 L, N, V;
    float distance = 0.0f;
    if (const ProbeLight *p = probedLight(s, light)) {
        plot.probed = true;
        in = p->inputs;
        L = p->terms.L;
        N = p->terms.N;
        V = p->terms.V;
        distance = p->terms.distance;
    } else {
        in = lightingInputs(scene, s.frames, light);
        const glm::vec3 centre = s.centre();
        L = lightVector(in.lightEye, centre);
        V = viewVector(centre, in.projection);
        N = V;
        if (in.lightEye.w != 0.0f)
            distance = glm::length(glm::vec3(in.lightEye) - centre);
    }
    // A point light at the point itself: L has no direction, so neither has any term but the
    // ambient; every sample was NaN (and each drawn one a warning). Said, not drawn.
    if (!(glm::length(L) > 0.5f) || (in.lightEye.w != 0.0f && !(distance > 1e-6f))) {
        plot.gap = PlotGap::LightAtPoint;
        return plot;
    }
    // The plane of incidence: N and the part of L across it (any direction across N where L
    // is along N).
    glm::vec3 across = L - glm::dot(L, N) * N;
    if (glm::length(across) < 1e-4f)
        across = glm::cross(N, std::abs(N.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    across = glm::normalize(across);
    const auto viewAt = [&](float degrees) {
        const float a = glm::radians(degrees);
        return std::cos(a) * N + std::sin(a) * across;
    };
    const glm::vec3 id = in.colors.id;
    PlotSeries terms[3] = {{QStringLiteral("ambient"), PlotRole::Ambient, light, id, false, {}},
                           {QStringLiteral("diffuse"), PlotRole::Diffuse, light, id, false, {}},
                           {QStringLiteral("specular"), PlotRole::Specular, light, id, false, {}}};
    const auto addSample = [&](float degrees, std::vector<glm::vec2> *to[3]) {
        const LightingTerms t = lightingTerms(L, N, viewAt(degrees), distance, in);
        const float values[3] = {mean(t.ambient), mean(t.diffuse), mean(t.specular)};
        for (int k = 0; k < 3; ++k)
            to[k]->push_back({degrees, values[k]});
    };
    std::vector<glm::vec2> *curves[3] = {&terms[0].points, &terms[1].points, &terms[2].points};
    for (int i = 0; i < samples; ++i)
        addSample(sampleAt(i, samples, plot.xMin, plot.xMax), curves);
    float reach = 0.0f;
    for (const PlotSeries &t : terms)
        for (const glm::vec2 &p : t.points)
            reach = std::max(reach, p.y);
    reach = reach > 0.0f ? reach : 1.0f;
    for (PlotSeries &t : terms)
        plot.series.push_back(std::move(t));
    // L, its mirror R and V as rays from the point, where they lie in front of the surface.
    const float lightAngle = degreesFromCosine(glm::dot(L, N));
    const float viewAngle =
        glm::degrees(std::atan2(glm::dot(V, across), glm::dot(V, N))); // V across the plane
    const std::pair<const char *, float> rays[] = {
        {"L", lightAngle}, {"R", -lightAngle}, {"V", viewAngle}};
    for (const auto &[key, angle] : rays)
        if (angle >= plot.xMin && angle <= plot.xMax)
            plot.series.push_back({QString::fromLatin1(key),
                                   PlotRole::Direction,
                                   light,
                                   id,
                                   false,
                                   {{angle, 0.0f}, {angle, reach}}});
    // The three contributions where V is (its part in the plane), on their curves.
    if (plot.probed && viewAngle >= plot.xMin && viewAngle <= plot.xMax) {
        std::vector<glm::vec2> at[3];
        std::vector<glm::vec2> *to[3] = {&at[0], &at[1], &at[2]};
        addSample(viewAngle, to);
        for (int k = 0; k < 3; ++k)
            plot.markers.push_back({k, light, in.colors.id, at[k].front()});
    }
    return plot;
}

} // namespace

QString plotKindName(PlotKind kind)
{
    switch (kind) {
    case PlotKind::Specular:
        return QStringLiteral("specular");
    case PlotKind::Diffuse:
        return QStringLiteral("diffuse");
    case PlotKind::Attenuation:
        return QStringLiteral("attenuation");
    case PlotKind::Spot:
        return QStringLiteral("spot");
    case PlotKind::Lobe:
        return QStringLiteral("lobe");
    }
    return {};
}

std::optional<PlotKind> plotKindFromName(const QString &name)
{
    for (PlotKind kind : kPlotKinds)
        if (plotKindName(kind) == name)
            return kind;
    return std::nullopt;
}

QStringList plotKindNames()
{
    QStringList names;
    for (PlotKind kind : kPlotKinds)
        names << plotKindName(kind);
    return names;
}

Plot computePlot(PlotKind kind, const Scene &scene, const ProbeResult *probe, int samples)
{
    samples = std::max(samples, 2);
    const PlotSubject s = subjectOf(scene, probe);
    Plot plot;
    switch (kind) {
    case PlotKind::Specular:
        plot = specularPlot(scene, s, samples);
        break;
    case PlotKind::Diffuse:
        plot = diffusePlot(scene, s, samples);
        break;
    case PlotKind::Attenuation:
        plot = attenuationPlot(scene, s, samples);
        break;
    case PlotKind::Spot:
        plot = spotPlot(scene, s, samples);
        break;
    case PlotKind::Lobe:
        plot = lobePlot(scene, s, samples);
        break;
    }
    plot.kind = kind;
    plot.shininess = scene.objects[std::size_t(s.object)].material.shininess;
    plot.probed = plot.probed || s.probe;
    return plot;
}

QByteArray plotCsv(const Plot &plot)
{
    std::vector<const PlotSeries *> columns;
    for (const PlotSeries &series : plot.series)
        if (series.role != PlotRole::Direction)
            columns.push_back(&series);
    QByteArray csv = plot.kind == PlotKind::Attenuation ? "distance" : "angle_degrees";
    for (const PlotSeries *series : columns)
        csv += ',' + series->key.toLatin1();
    csv += '\n';
    const std::size_t rows = columns.empty() ? 0 : columns.front()->points.size();
    for (std::size_t r = 0; r < rows; ++r) {
        csv += QByteArray::number(double(columns.front()->points[r].x), 'g', 9);
        for (const PlotSeries *series : columns)
            csv += ',' + QByteArray::number(double(series->points[r].y), 'g', 9);
        csv += '\n';
    }
    return csv;
}

} // namespace lb
