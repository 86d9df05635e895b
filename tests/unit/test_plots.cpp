// The Plots panel's curves (plots.h) against the formulas written out here, independently of
// lighting.cpp: max(cos θ, 0)^n for Phong, cos(θ/2)^n and cos(θ/2)^(4n) for Blinn-Phong, max(cos α,
// 0), 1 / (kc + kl·d + kq·d²), a spotlight's cos(β)^e inside its cone; at n = 1 and n = 1000, spot
// exponent 0, kq alone. On a probed sphere each mark carries the probe's own value and lies on its
// curve. The CSV has one row per sample.
#include "mesh.h"
#include "plots.h"

#include <QTest>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

Q_DECLARE_METATYPE(glm::vec3)
Q_DECLARE_METATYPE(lb::SpecularModel)

using namespace lb;

namespace {

const QSize kView(400, 300);
const QPoint kPixel(210, 140);

double radians(double degrees)
{
    return degrees * M_PI / 180.0;
}

const PlotSeries *seriesNamed(const Plot &plot, const QString &key)
{
    for (const PlotSeries &s : plot.series)
        if (s.key == key)
            return &s;
    return nullptr;
}

// The series' value at x, read off its straight pieces.
double curveAt(const PlotSeries &s, double x)
{
    for (std::size_t i = 1; i < s.points.size(); ++i)
        if (x <= s.points[i].x) {
            const glm::vec2 a = s.points[i - 1], b = s.points[i];
            const double t = b.x > a.x ? (x - a.x) / (b.x - a.x) : 0.0;
            return a.y + t * (b.y - a.y);
        }
    return s.points.back().y;
}

// Compares every sample of `key` with `expected(x)` (none: not compared) within `tolerance`
// (relative above 1); `failure` names the first one that differs.
struct Comparison
{
    int compared = 0;
    QString failure;
};
template <typename F>
Comparison compareSeries(const Plot &plot, const QString &key, F expected, double tolerance = 2e-5)
{
    Comparison c;
    const PlotSeries *s = seriesNamed(plot, key);
    if (!s) {
        c.failure = "no series " + key;
        return c;
    }
    for (const glm::vec2 &p : s->points) {
        const std::optional<double> want = expected(double(p.x));
        if (!want)
            continue;
        const double scale = std::max(1.0, std::abs(*want));
        if (std::abs(double(p.y) - *want) > tolerance * scale && c.failure.isEmpty())
            c.failure = QString("%1 at %2: %3, expected %4")
                            .arg(key)
                            .arg(double(p.x))
                            .arg(double(p.y), 0, 'g', 9)
                            .arg(*want, 0, 'g', 9);
        ++c.compared;
    }
    return c;
}

// Every sample compared (`count` of them) and equal.
#define COMPARE_SERIES(comparison, count)                                                          \
    do {                                                                                           \
        const Comparison c_ = (comparison);                                                        \
        QVERIFY2(c_.failure.isEmpty(), qPrintable(c_.failure));                                    \
        QCOMPARE(c_.compared, count);                                                              \
    } while (false)

Scene spotScene()
{
    Scene s;
    s.lights[0].spot.direction = glm::vec3(0.0f, -1.8f, -1.3f); // at the sphere's centre
    s.lights[0].spot.cutoffDegrees = 40.0f;
    s.lights[0].spot.exponent = 8.0f;
    return s;
}

} // namespace

class TestPlots : public QObject
{
    Q_OBJECT
private:
    Mesh m_sphere = makeSphere(48, 48);
    Texture m_checker;

    ProbeResult probe(const Scene &scene) const
    {
        return probePixel(scene, {{&m_sphere, &m_checker}}, kView, kPixel);
    }

private slots:
    void namesGoBothWays()
    {
        for (PlotKind kind : kPlotKinds)
            QCOMPARE(plotKindFromName(plotKindName(kind)), kind);
        QVERIFY(!plotKindFromName("Specular").has_value());
        QVERIFY(!plotKindFromName({}).has_value());
    }

    void specularCurves_data()
    {
        QTest::addColumn<float>("shininess");
        for (float n : {1.0f, 2.0f, 6.0f, 20.0f, 128.0f, 250.0f, 1000.0f})
            QTest::addRow("n=%g", double(n)) << n;
    }
    void specularCurves()
    {
        QFETCH(float, shininess);
        Scene s;
        s.objects[0].material.shininess = shininess;
        const Plot plot = computePlot(PlotKind::Specular, s);
        QCOMPARE(plot.shininess, shininess);
        QCOMPARE(plot.xMin, 0.0f);
        QCOMPARE(plot.xMax, 180.0f);
        const double n = shininess;
        // pow() magnifies float's error in the cosine (about 1e-7) by the exponent.
        const double tolerance = 2e-5 + 5e-7 * n;
        COMPARE_SERIES(
            compareSeries(
                plot, "phong",
                [&](double x) { return std::pow(std::max(std::cos(radians(x)), 0.0), n); },
                tolerance),
            kPlotSamples);
        COMPARE_SERIES(compareSeries(
                           plot, "blinn",
                           [&](double x) { return std::pow(std::cos(radians(x / 2)), n); },
                           tolerance),
                       kPlotSamples);
        COMPARE_SERIES(compareSeries(
                           plot, "blinn_4n",
                           [&](double x) { return std::pow(std::cos(radians(x / 2)), 4 * n); },
                           4 * tolerance),
                       kPlotSamples);
        QVERIFY(seriesNamed(plot, "blinn_4n")->dashed);
        QVERIFY(!seriesNamed(plot, "phong")->dashed);
    }

    void diffuseCurve()
    {
        const Plot plot = computePlot(PlotKind::Diffuse, Scene{}, nullptr, 361);
        QCOMPARE(plot.xMax, 180.0f);
        COMPARE_SERIES(compareSeries(plot, "diffuse",
                                     [](double x) { return std::max(std::cos(radians(x)), 0.0); }),
                       361);
    }

    void attenuationCurves_data()
    {
        QTest::addColumn<glm::vec3>("k");
        QTest::addRow("none") << glm::vec3(1, 0, 0);
        QTest::addRow("kq only") << glm::vec3(0, 0, 1);
        QTest::addRow("kl only") << glm::vec3(0, 0.5f, 0);
        QTest::addRow("all three") << glm::vec3(1, 0.5f, 0.25f);
        QTest::addRow("weak kc") << glm::vec3(0.2f, 0, 0);
        QTest::addRow("strong") << glm::vec3(1, 2, 1000);
    }
    void attenuationCurves()
    {
        QFETCH(glm::vec3, k);
        Scene s;
        s.lights[0].attenuation = k;
        s.lights[1].enabled = true; // a second point light with its own constants
        s.lights[1].position.w = 1.0f;
        s.lights[1].attenuation = glm::vec3(1.0f, 0.0f, 0.5f);
        s.lights[2].enabled = true; // directional: no curve
        s.lights[2].position.w = 0.0f;
        const Plot plot = computePlot(PlotKind::Attenuation, s);
        QCOMPARE(plot.gap, PlotGap::None);
        QVERIFY(plot.xMax >= 5.0f);
        QVERIFY(!seriesNamed(plot, "light3"));
        QVERIFY(!seriesNamed(plot, "light4"));
        const auto expected = [](glm::vec3 c) {
            return [c](double d) { return 1.0 / std::max(c.x + c.y * d + c.z * d * d, 1e-6); };
        };
        COMPARE_SERIES(compareSeries(plot, "light1", expected(k), 1e-4), kPlotSamples);
        COMPARE_SERIES(compareSeries(plot, "light2", expected(glm::vec3(1, 0, 0.5f)), 1e-4),
                       kPlotSamples);
        s.lights[0].position.w = 0.0f;
        s.lights[1].enabled = false;
        QCOMPARE(computePlot(PlotKind::Attenuation, s).gap, PlotGap::NoPointLight);
    }

    void spotCurves_data()
    {
        QTest::addColumn<float>("cutoff");
        QTest::addColumn<float>("exponent");
        QTest::addRow("exponent 0") << 30.0f << 0.0f;
        QTest::addRow("soft") << 45.0f << 2.0f;
        QTest::addRow("sharp") << 20.0f << 128.0f;
        QTest::addRow("wide") << 120.0f << 1.0f;
        QTest::addRow("narrow") << 1.0f << 10.0f;
    }
    void spotCurves()
    {
        QFETCH(float, cutoff);
        QFETCH(float, exponent);
        Scene s = spotScene();
        s.lights[0].spot.cutoffDegrees = cutoff;
        s.lights[0].spot.exponent = exponent;
        const Plot plot = computePlot(PlotKind::Spot, s);
        QCOMPARE(plot.xMax, cutoff < 80.0f ? 90.0f : 180.0f);
        const Comparison c = compareSeries(plot, "light1", [&](double x) -> std::optional<double> {
            if (std::abs(x - cutoff) < 0.01) // on the edge: float and double may differ
                return std::nullopt;
            if (x > cutoff)
                return 0.0;
            return exponent == 0.0f
                       ? 1.0
                       : std::pow(std::max(std::cos(radians(x)), 0.0), double(exponent));
        });
        QVERIFY2(c.failure.isEmpty(), qPrintable(c.failure));
        QVERIFY(c.compared >= kPlotSamples - 1);
        s.lights[0].spot.cutoffDegrees = 180.0f;
        QCOMPARE(computePlot(PlotKind::Spot, s).gap, PlotGap::NoSpotlight);
    }

    // Each mark is the probe's own value, and on its curve.
    void marksCarryTheProbesValues_data()
    {
        QTest::addColumn<SpecularModel>("model");
        QTest::addRow("Phong") << SpecularModel::Phong;
        QTest::addRow("Blinn-Phong") << SpecularModel::Blinn;
    }
    void marksCarryTheProbesValues()
    {
        QFETCH(SpecularModel, model);
        Scene s = spotScene();
        s.shading.specular = model;
        s.lights[0].attenuation = glm::vec3(0.5f, 0.2f, 0.1f);
        s.objects[0].material.shininess = 40.0f;
        const ProbeResult p = probe(s);
        QVERIFY(p.hit);
        QCOMPARE(int(p.lights.size()), 1);
        const LightingTerms &t = p.lights[0].terms;
        QVERIFY(t.nDotL > 0.0f && t.spot > 0.0f);
        const int dense = 20001;

        Plot plot = computePlot(PlotKind::Specular, s, &p, dense);
        QCOMPARE(int(plot.markers.size()), 1);
        PlotMarker m = plot.markers[0];
        QCOMPARE(plot.series[std::size_t(m.series)].key,
                 model == SpecularModel::Phong ? QString("phong") : QString("blinn"));
        QCOMPARE(m.at.y, t.specularFactor);
        QVERIFY(std::abs(curveAt(plot.series[std::size_t(m.series)], m.at.x) - m.at.y) < 1e-3);

        plot = computePlot(PlotKind::Diffuse, s, &p, dense);
        m = plot.markers.at(0);
        QCOMPARE(m.at.y, t.nDotL);
        QVERIFY(std::abs(std::cos(radians(m.at.x)) - t.nDotL) < 1e-5);
        QVERIFY(std::abs(curveAt(plot.series[0], m.at.x) - m.at.y) < 1e-4);

        plot = computePlot(PlotKind::Attenuation, s, &p, dense);
        m = plot.markers.at(0);
        QCOMPARE(m.at, glm::vec2(t.distance, t.attenuation));
        QVERIFY(std::abs(curveAt(plot.series[0], m.at.x) - m.at.y) < 1e-4);

        plot = computePlot(PlotKind::Spot, s, &p, dense);
        m = plot.markers.at(0);
        QCOMPARE(m.at.y, t.spot);
        QVERIFY(std::abs(curveAt(plot.series[0], m.at.x) - m.at.y) < 1e-3);
        QVERIFY(m.at.x < 40.0f);
    }

    // The lobe at the probed point: ambient and diffuse the same from every direction (and the
    // probe's), the specular term Phong's peak at R, the directions L, R, V where they are.
    void lobeAtTheProbedPoint()
    {
        Scene s;
        s.shading.specular = SpecularModel::Phong;
        s.objects[0].material.shininess = 12.0f;
        const ProbeResult p = probe(s);
        QVERIFY(p.hit);
        const LightingTerms &t = p.lights[0].terms;
        const auto mean = [](glm::vec3 c) { return double(c.r + c.g + c.b) / 3.0; };
        const Plot plot = computePlot(PlotKind::Lobe, s, &p);
        QVERIFY(plot.polar && plot.probed);
        QCOMPARE(plot.xMin, -90.0f);
        QCOMPARE(plot.xMax, 90.0f);
        COMPARE_SERIES(compareSeries(plot, "ambient", [&](double) { return mean(t.ambient); }),
                       kPlotSamples);
        COMPARE_SERIES(compareSeries(plot, "diffuse", [&](double) { return mean(t.diffuse); }),
                       kPlotSamples);
        const double lightAngle = std::acos(double(t.nDotL)) * 180.0 / M_PI;
        const PlotSeries *L = seriesNamed(plot, "L");
        const PlotSeries *R = seriesNamed(plot, "R");
        QVERIFY(L && R && seriesNamed(plot, "V"));
        QVERIFY(std::abs(L->points[0].x - lightAngle) < 1e-3);
        QVERIFY(std::abs(R->points[0].x + lightAngle) < 1e-3);
        // Phong: (R·V)^n, with V in the plane at angle φ: R·V = cos(φ + θL).
        const glm::vec3 peak = p.lights[0].inputs.colors.is * p.lights[0].inputs.material.ks;
        const double scale = double(t.attenuation * t.spot) * mean(peak);
        COMPARE_SERIES(compareSeries(plot, "specular",
                                     [&](double phi) {
                                         const double c = std::cos(radians(phi + lightAngle));
                                         return scale * std::pow(std::max(c, 0.0), 12.0);
                                     }),
                       kPlotSamples);
        // The marks: on the three curves at V's angle, ambient and diffuse the probe's own.
        QCOMPARE(int(plot.markers.size()), 3);
        QVERIFY(std::abs(plot.markers[0].at.y - mean(t.ambient)) < 1e-5);
        QVERIFY(std::abs(plot.markers[1].at.y - mean(t.diffuse)) < 1e-5);
        // V's angle in the plane of incidence, worked out here: atan2 of V along the plane's
        // direction across N (towards L) and along N; the specular mark is Phong's value there.
        const glm::dvec3 n(t.N), l(t.L), v(t.V);
        const glm::dvec3 across = glm::normalize(l - glm::dot(l, n) * n);
        const double phi = std::atan2(glm::dot(v, across), glm::dot(v, n)) * 180.0 / M_PI;
        for (const PlotMarker &m : plot.markers)
            QVERIFY2(std::abs(m.at.x - phi) < 1e-3, qPrintable(QString::number(m.at.x)));
        const double atV =
            scale * std::pow(std::max(std::cos(radians(phi + lightAngle)), 0.0), 12.0);
        QVERIFY2(std::abs(plot.markers[2].at.y - atV) < 1e-5,
                 qPrintable(QString("%1 for %2").arg(plot.markers[2].at.y).arg(atV)));
        QCOMPARE(plot.lobeLight, 0);

        Scene dark;
        for (Light &l : dark.lights)
            l.enabled = false;
        QCOMPARE(computePlot(PlotKind::Lobe, dark).gap, PlotGap::NoLight);
        const Plot unprobed = computePlot(PlotKind::Lobe, s);
        QVERIFY(!unprobed.probed && unprobed.markers.empty());
        QCOMPARE(int(unprobed.series.size()), 6); // the terms, L, R and V (along N)
    }

    // Two lights on, the second behind the sphere: each mark is its own light's, the one behind
    // has no highlight (no specular mark) and its diffuse mark sits at 0 beyond 90 degrees. The
    // marks follow the model the probe used (side B's in a compare view), not the scene's.
    void marksOfSeveralLights()
    {
        Scene s;
        s.lights[1].enabled = true;
        s.lights[1].position = glm::vec4(0.0f, 0.0f, -6.0f, 1.0f); // world: behind the sphere
        s.lights[1].frame = LightFrame::World;
        s.lights[1].colors.id = glm::vec3(0.2f, 0.4f, 1.0f);
        const ProbeResult p = probe(s);
        QVERIFY(p.hit);
        QCOMPARE(int(p.lights.size()), 2);
        QVERIFY(p.lights[0].terms.nDotL > 0.0f);
        QVERIFY(p.lights[1].terms.nDotL < 0.0f);

        Plot plot = computePlot(PlotKind::Specular, s, &p);
        QCOMPARE(int(plot.markers.size()), 1);
        QCOMPARE(plot.markers[0].light, 0);
        plot = computePlot(PlotKind::Diffuse, s, &p);
        QCOMPARE(int(plot.markers.size()), 2);
        QCOMPARE(plot.markers[1].light, 1);
        QCOMPARE(plot.markers[1].lightDiffuse, glm::vec3(0.2f, 0.4f, 1.0f));
        QVERIFY(plot.markers[1].at.x > 90.0f);
        QCOMPARE(plot.markers[1].at.y, 0.0f);
        QVERIFY(std::abs(plot.markers[0].at.y - p.lights[0].terms.nDotL) < 1e-6f);

        // Probed with Blinn-Phong, plotted with a scene that says Phong: the mark is on the
        // Blinn-Phong curve, at 2·acos(N·H).
        Scene phong = s;
        phong.shading.specular = SpecularModel::Phong;
        plot = computePlot(PlotKind::Specular, phong, &p);
        QCOMPARE(plot.series[std::size_t(plot.markers.at(0).series)].key, QString("blinn"));
        const double half = std::acos(double(p.lights[0].terms.specularAngle)) * 180.0 / M_PI;
        QVERIFY(std::abs(plot.markers[0].at.x - 2.0 * half) < 1e-3);
    }

    // N·H < 0 with the light in front (a surface seen from behind): Blinn-Phong's factor is 0
    // and 2·acos(N·H) would lie beyond 180: no dot. Phong's R·V < 0 is a dot at 0 on its curve.
    void noDotBeyondTheAxis()
    {
        ProbeResult r;
        r.hit = true;
        ProbeLight light;
        light.inputs.specular = SpecularModel::Blinn;
        light.terms.nDotL = 0.5f;
        light.terms.specularAngle = -0.2f;
        light.terms.specularFactor = 0.0f;
        r.lights.push_back(light);
        QVERIFY(computePlot(PlotKind::Specular, Scene{}, &r).markers.empty());
        r.lights[0].inputs.specular = SpecularModel::Phong;
        const Plot phong = computePlot(PlotKind::Specular, Scene{}, &r);
        QCOMPARE(int(phong.markers.size()), 1);
        QVERIFY(phong.markers[0].at.x > 90.0f && phong.markers[0].at.x <= 180.0f);
        QCOMPARE(phong.markers[0].at.y, 0.0f);
    }

    // The diffuse factor the plots share with evaluateLighting is glm::max's: a NaN passes
    // through (a broken normal shows), -0 stays -0.
    void diffuseFactorIsGlmMax()
    {
        for (float v : {-1.0f, -0.0f, 0.0f, 0.25f, 1.0f, std::nanf("")}) {
            const float ours = diffuseFactor(v), glms = glm::max(v, 0.0f);
            QCOMPARE(std::isnan(ours), std::isnan(glms));
            if (!std::isnan(glms)) {
                QCOMPARE(ours, glms);
                QCOMPARE(std::signbit(ours), std::signbit(glms));
            }
        }
    }

    void csvHasARowPerSample()
    {
        Scene s;
        s.lights[1].enabled = true;
        s.lights[1].position.w = 1.0f;
        const Plot plot = computePlot(PlotKind::Attenuation, s, nullptr, 11);
        const QList<QByteArray> lines = plotCsv(plot).split('\n');
        QCOMPARE(lines.size(), 13); // header, 11 rows, the empty piece after the last newline
        QCOMPARE(lines[0], QByteArray("distance,light1,light2"));
        QVERIFY(lines[12].isEmpty());
        for (int r = 0; r < 11; ++r) {
            const QList<QByteArray> cells = lines[r + 1].split(',');
            QCOMPARE(cells.size(), 3);
            QCOMPARE(cells[0].toFloat(), plot.series[0].points[std::size_t(r)].x);
            QCOMPARE(cells[1].toFloat(), plot.series[0].points[std::size_t(r)].y);
            QCOMPARE(cells[2].toFloat(), plot.series[1].points[std::size_t(r)].y);
        }
        const QByteArray lobe = plotCsv(computePlot(PlotKind::Lobe, s, nullptr, 3));
        QVERIFY2(lobe.startsWith("angle_degrees,ambient,diffuse,specular\n-90,"), lobe.constData());
    }
};

QTEST_GUILESS_MAIN(TestPlots)
#include "test_plots.moc"
