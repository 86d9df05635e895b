#pragma once
// The model's curves beside the surface: the specular factor against the angle from the
// mirror direction, the diffuse factor against the angle of incidence, each point light's
// attenuation against the distance, each spotlight's factor against the angle from its axis,
// and the lobe of the three terms in the plane of incidence. Every sample is the model's own
// function (lighting.h: lightingTerms, attenuationFactor, spotFactor) at swept inputs, never a
// second formula; the probed point's own values are marked on the curves.

#include "probe.h"
#include "scene.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace lb {

enum class PlotKind { Specular, Diffuse, Attenuation, Spot, Lobe };
constexpr PlotKind kPlotKinds[] = {PlotKind::Specular, PlotKind::Diffuse, PlotKind::Attenuation,
                                   PlotKind::Spot, PlotKind::Lobe};
// "specular", "diffuse", "attenuation", "spot", "lobe": the command line's and the settings'.
QString plotKindName(PlotKind kind);
std::optional<PlotKind> plotKindFromName(const QString &name);
QStringList plotKindNames();

// What a series stands for, which gives its colour: a term, a light, or a direction of the
// lobe's picture.
enum class PlotRole { Ambient, Diffuse, Specular, Light, Direction };

struct PlotSeries
{
    // Names the CSV column and (translated) the legend: phong, blinn, blinn_4n, diffuse,
    // light1..light4, ambient, specular; L, R, V for the lobe's directions.
    QString key;
    PlotRole role = PlotRole::Specular;
    int light = -1;               // 0 for light 1, where the series is a light's
    glm::vec3 lightDiffuse{1.0f}; // that light's Id: its L arrow's colour over the surface
    bool dashed = false;
    std::vector<glm::vec2> points; // x: degrees or distance; y: the factor or contribution
};

// The probed point's own value on a series: x its angle or distance, y what the model gives
// it there (so it lies on the curve).
struct PlotMarker
{
    int series = 0;               // index into Plot::series
    int light = 0;                // whose value it is
    glm::vec3 lightDiffuse{1.0f}; // that light's Id (the dot's colour where several are on)
    glm::vec2 at{0.0f};
};

// Why a plot has no curve to draw.
// LightAtPoint: the lobe's point light is at the point itself, where L has no direction.
enum class PlotGap { None, NoPointLight, NoSpotlight, NoLight, LightAtPoint };

struct Plot
{
    PlotKind kind = PlotKind::Specular;
    // The lobe: x is the angle of V from N in the plane of incidence, in degrees (towards L
    // positive, -90 to 90), y the contribution (the mean of its red, green and blue).
    bool polar = false;
    float xMin = 0.0f, xMax = 90.0f;
    float shininess = 1.0f; // the exponent of the specular curves (the material's)
    std::vector<PlotSeries> series;
    std::vector<PlotMarker> markers;
    PlotGap gap = PlotGap::None;
    // The lobe without a probed point is drawn where the selected object's centre faces the
    // camera (N towards the eye); with one, at that point. It is the first light's that is on
    // (`lobeLight`); its V marks are where V's part in the plane of incidence points, so the
    // specular mark is the probe's own value only where V lies in that plane.
    bool probed = false;
    int lobeLight = 0;
};

constexpr int kPlotSamples = 361; // a half degree apart over 0 to 180, a quarter over 0 to 90

// The plot of `kind` for `scene`: the material and lights of the probed object where `probe`
// hit one (its values marked), else of the selected object. `samples` at least 2.
Plot computePlot(PlotKind kind, const Scene &scene, const ProbeResult *probe = nullptr,
                 int samples = kPlotSamples);

// The samples as CSV for machines: a header (angle_degrees or distance, then each series'
// key), a row per sample, numbers with a point; the lobe's directions are left out.
QByteArray plotCsv(const Plot &plot);

} // namespace lb
