// The probe's attenuation and spot at points worked out by hand, and the Probe panel's equation
// with the numbers in it (probe_equation.h), on a probed sphere: the symbols follow Phong /
// Blinn-Phong and the terms switched on, each light's line carries the probe's own factors and
// terms, and the sum and the pixel are the reference's.
#include "mesh.h"
#include "probe.h"
#include "probe_equation.h"

#include <QRegularExpression>
#include <QTest>

#include <cmath>

using namespace lb;

namespace {

const QSize kView(400, 300);

QString fixed(float v)
{
    return QString::number(double(v), 'f', 4);
}

} // namespace

class TestProbeEquation : public QObject
{
    Q_OBJECT
private:
    Mesh m_sphere = makeSphere(32, 32);
    Texture m_checker;

    ProbeResult probe(const Scene &scene) const
    {
        return probePixel(scene, {{&m_sphere, &m_checker}}, kView, QPoint(210, 140));
    }

private slots:
    void symbolsFollowTheSpecularModelAndTheTerms()
    {
        Scene s;
        s.shading.specular = SpecularModel::Phong;
        QString text = lightingEquation(s, probe(s));
        QString first = text.section('\n', 0, 0);
        QVERIFY2(first.contains("Ia·Ka + Id·Kd·max(N·L, 0) + Is·Ks·max(R·V, 0)^n"),
                 qPrintable(first));
        s.shading.specular = SpecularModel::Blinn;
        s.shading.terms.ambient = false;
        text = lightingEquation(s, probe(s));
        first = text.section('\n', 0, 0);
        QVERIFY2(first.contains("att·spot·(Id·Kd·max(N·L, 0) + Is·Ks·max(N·H, 0)^n)"),
                 qPrintable(first));
        QVERIFY(!first.contains("Ia·Ka"));
        QVERIFY(text.contains("[off] att·spot·Ia·Ka")); // still listed, marked
        QVERIFY(lightingEquation(s, ProbeResult{}).isEmpty());
    }

    // Two lights, the first attenuated and a spotlight: the numbers are the probe's, and the
    // last lines give the reference's sum and pixel.
    void numbersAreTheProbes()
    {
        Scene s;
        s.lights[0].frame = LightFrame::Camera;
        s.lights[0].position = {0.5f, 0.5f, 0.0f, 1.0f};
        s.lights[0].attenuation = {1.0f, 0.0f, 1.0f};
        s.lights[0].spot = {{0.0f, 0.0f, -1.0f}, 60.0f, 2.0f};
        s.lights[1].enabled = true;
        const ProbeResult p = probe(s);
        QVERIFY(p.hit);
        QCOMPARE(int(p.lights.size()), 2);
        const LightingTerms &t = p.lights[0].terms;
        // 1 / (1 + d²) by hand from the probe's distance.
        QVERIFY(std::abs(t.attenuation - 1.0f / (1.0f + t.distance * t.distance)) < 1e-6f);
        QVERIFY(t.spot > 0.0f && t.spot < 1.0f);
        const QString text = lightingEquation(s, p);
        qInfo("%s", qPrintable(text));
        QVERIFY2(text.contains(QString("light 1: att·spot = %1·%2 = %3 (d = %4)")
                                   .arg(fixed(t.attenuation), fixed(t.spot),
                                        fixed(t.attenuation * t.spot), fixed(t.distance))),
                 qPrintable(text));
        QVERIFY(
            text.contains(QString("= (%1, %2, %3)")
                              .arg(fixed(t.diffuse.x), fixed(t.diffuse.y), fixed(t.diffuse.z))));
        QVERIFY(text.contains("light 2: att·spot = 1.0000·1.0000 = 1.0000 (d = "));
        const glm::vec3 sum = p.total.ambient + p.total.diffuse + p.total.specular;
        QVERIFY2(text.contains(
                     QString("= (%1, %2, %3)\n").arg(fixed(sum.x), fixed(sum.y), fixed(sum.z))),
                 qPrintable(text));
        QVERIFY(text.contains(QString("pixel = (%1, %2, %3) of 255")
                                  .arg(std::lround(p.reference.r * 255.0f))
                                  .arg(std::lround(p.reference.g * 255.0f))
                                  .arg(std::lround(p.reference.b * 255.0f))));
    }

    // The probe's spot factor at a point worked out by hand: a light in camera space at the
    // eye, its cone's axis straight ahead; at a probed point P the angle off the axis is
    // acos(dot(normalize(P), (0, 0, -1))). A cutoff half a degree above it: inside, cos^4;
    // half a degree below: outside, nothing at all.
    void spotFactorInsideAndOutsideTheCutoff()
    {
        Scene s;
        s.lights[0].frame = LightFrame::Camera;
        s.lights[0].position = {0.0f, 0.0f, 0.0f, 1.0f};
        s.lights[0].spot = {{0.0f, 0.0f, -1.0f}, 180.0f, 4.0f};
        const ProbeResult plain = probe(s);
        QVERIFY(plain.hit);
        const glm::vec3 P = plain.position;
        const float cosAngle = -P.z / std::sqrt(P.x * P.x + P.y * P.y + P.z * P.z);
        const float degrees = std::acos(cosAngle) * 180.0f / 3.14159265f;
        QVERIFY(degrees > 2.0f); // off the axis, so that half a degree either way is clear
        s.lights[0].spot.cutoffDegrees = degrees + 0.5f;
        const ProbeResult inside = probe(s);
        QVERIFY(std::abs(inside.lights[0].terms.spot - std::pow(cosAngle, 4.0f)) < 1e-4f);
        QVERIFY(inside.lights[0].terms.diffuse.r > 0.0f);
        s.lights[0].spot.cutoffDegrees = degrees - 0.5f;
        const ProbeResult outside = probe(s);
        QCOMPARE(outside.lights[0].terms.spot, 0.0f);
        QCOMPARE(outside.total.ambient + outside.total.diffuse + outside.total.specular,
                 glm::vec3(0.0f));
    }

    // Issue 50: the lines are patterns with parts, filled in one pass: a part's own "%1" (a
    // number's text never has one, a phrase might in another language) is not filled again,
    // and the panel translates patterns and phrases instead of parsing English back.
    void linesAreFilledOnce()
    {
        QCOMPARE(fillPattern("light %1: %2", {"%2", "x"}), QString("light %2: x"));
        QCOMPARE(fillPattern("100% of %1%", {"a"}), QString("100% of a%"));
        Scene s;
        s.shading.terms.diffuse = false;
        const std::vector<EquationLine> lines = lightingEquationLines(s, probe(s));
        QStringList text;
        for (const EquationLine &line : lines) {
            text << equationLineText(line);
            for (const EquationPart &part : line.parts)
                if (part.kind == EquationPart::Kind::Phrase)
                    QVERIFY(!part.text.isEmpty());
        }
        QCOMPARE(text.join('\n'), lightingEquation(s, probe(s)));
        QVERIFY(lightingEquation(s, probe(s)).contains("  [off] att·spot·Id·Kd·max(N·L, 0) = "));
    }

    // Issue 28: Copy the Equation gives the same text under a German default locale: its
    // numbers keep their points, as the probe, the JSON and the shaders write them.
    void numbersKeepTheirPointsInEveryLocale()
    {
        Scene s;
        s.objects[0].material.shininess = 12.5f;
        const QString c = lightingEquation(s, probe(s));
        const QLocale old;
        QLocale::setDefault(QLocale("de_DE"));
        const QString german = lightingEquation(s, probe(s));
        QLocale::setDefault(QLocale("pt_PT"));
        const QString portuguese = lightingEquation(s, probe(s));
        QLocale::setDefault(old);
        QCOMPARE(german, c);
        QCOMPARE(portuguese, c);
        QVERIFY(c.contains("^12.5") && c.contains(QRegularExpression("\\d\\.\\d{4}")));
    }

    void saysWhatThePixelIsNot()
    {
        Scene s;
        s.shading.shading = Shading::Gouraud;
        QVERIFY(lightingEquation(s, probe(s)).contains("interpolated"));
        s.shading.shading = Shading::Flat;
        QVERIFY(lightingEquation(s, probe(s)).contains("provoking"));
        s.shading.show = ShowChoice::Normal;
        QVERIFY(lightingEquation(s, probe(s)).contains("shows normal"));
        s.shading.lighting = false;
        QVERIFY(lightingEquation(s, probe(s)).contains("Lighting is off"));
    }
};

QTEST_GUILESS_MAIN(TestProbeEquation)
#include "test_probe_equation.moc"
