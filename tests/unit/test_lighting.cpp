// The CPU reference against values worked out by hand from the slides' formulas.
#include "lighting.h"

#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/epsilon.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

using namespace lb;

namespace {
bool near(const glm::vec3 &a, const glm::vec3 &b, float eps = 1e-5f)
{
    return glm::all(glm::epsilonEqual(a, b, eps));
}
LightingInputs inputs(const glm::vec4 &light, SpecularModel model = SpecularModel::Blinn,
                      Projection projection = Projection::Perspective)
{
    LightingInputs in;
    in.lightEye = light;
    in.specular = model;
    in.projection = projection;
    return in;
}
} // namespace

class TestLighting : public QObject
{
    Q_OBJECT
private slots:
    void lightVectorForPointAndDirection()
    {
        const glm::vec3 p(0, 0, -4);
        QVERIFY(near(lightVector({0, 0, 1, 0}, p), {0, 0, 1}));  // a direction: as given
        QVERIFY(near(lightVector({0, 3, -4, 1}, p), {0, 1, 0})); // a point: towards it
        QVERIFY(near(lightVector({0, 0, 10, 0}, p), {0, 0, 1})); // directions are normalised
    }

    void viewVectorFollowsProjection()
    {
        QVERIFY(near(viewVector({3, 0, -4}, Projection::Perspective), {-0.6f, 0, 0.8f}));
        QVERIFY(near(viewVector({3, 0, -4}, Projection::Orthographic), {0, 0, 1}));
    }

    void headOnLightGivesFullDiffuseAndSpecular()
    {
        // Light, eye and normal all along +Z: N.L = N.H = R.V = 1.
        for (SpecularModel m : {SpecularModel::Phong, SpecularModel::Blinn}) {
            const LightingTerms t =
                evaluateLighting({0, 0, -3}, {0, 0, 1}, inputs({0, 0, 1, 0}, m));
            QVERIFY(near(t.ambient, glm::vec3(0.2f, 0, 0))); // Ia * Ka
            QVERIFY(near(t.diffuse, glm::vec3(0.7f, 0, 0))); // Id * Kd
            QVERIFY(near(t.specular, glm::vec3(1.0f)));      // Is * Ks * 1^n
            QCOMPARE(t.nDotL, 1.0f);
        }
    }

    void reflectionMirrorsTheLightAboutTheNormal()
    {
        // L at 45 degrees in the XZ plane; R must be its mirror across N = +Z.
        const glm::vec3 L = glm::normalize(glm::vec3(1, 0, 1));
        const LightingTerms t =
            evaluateLighting({0, 0, -3}, {0, 0, 1}, inputs(glm::vec4(L, 0), SpecularModel::Phong));
        QVERIFY(near(t.R, glm::normalize(glm::vec3(-1, 0, 1))));
        QVERIFY(std::abs(glm::dot(t.R, t.N) - glm::dot(t.L, t.N)) < 1e-6f);
    }

    void specularExponentOfTheAngle()
    {
        // Parallel projection, V = +Z; light at 60 degrees from N = +Z: N.L = 0.5.
        // Phong: R.V = cos(60) = 0.5 -> 0.5^n. Blinn: H at 30 degrees -> cos(30)^n.
        const glm::vec3 L(std::sin(glm::radians(60.0f)), 0, 0.5f);
        LightingInputs in = inputs(glm::vec4(L, 0), SpecularModel::Phong, Projection::Orthographic);
        in.material.shininess = 4;
        LightingTerms t = evaluateLighting({0, 0, -3}, {0, 0, 1}, in);
        QVERIFY(std::abs(t.specular.x - std::pow(0.5f, 4.0f)) < 1e-5f);
        QVERIFY(std::abs(t.diffuse.x - 0.7f * 0.5f) < 1e-5f);
        in.specular = SpecularModel::Blinn;
        t = evaluateLighting({0, 0, -3}, {0, 0, 1}, in);
        QVERIFY(std::abs(t.specular.x - std::pow(std::cos(glm::radians(30.0f)), 4.0f)) < 1e-5f);
    }

    void noLightFromBehind()
    {
        // Light below the surface: no diffuse, and no specular even though N.H > 0 here.
        const glm::vec3 L = glm::normalize(glm::vec3(0, 1, -0.2f));
        LightingInputs in = inputs(glm::vec4(L, 0), SpecularModel::Blinn, Projection::Orthographic);
        const LightingTerms t = evaluateLighting({0, 0, -3}, {0, 0, 1}, in);
        QVERIFY(t.nDotL < 0);
        QVERIFY(glm::dot(t.N, t.H) > 0);
        QVERIFY(near(t.diffuse, glm::vec3(0)));
        QVERIFY(near(t.specular, glm::vec3(0)));
        QVERIFY(near(t.ambient, glm::vec3(0.2f, 0, 0)));
    }

    // A point light 2 units straight above the point: d = 2, so with kc = 1, kl = 0.5,
    // kq = 0.25 the factor is 1 / (1 + 1 + 1) = 1/3 on all three terms.
    void attenuationAtAKnownDistance()
    {
        LightingInputs in = inputs({0, 2, -3, 1});
        in.attenuation = {1.0f, 0.5f, 0.25f};
        const LightingTerms plain = evaluateLighting({0, 0, -3}, {0, 1, 0}, inputs({0, 2, -3, 1}));
        const LightingTerms t = evaluateLighting({0, 0, -3}, {0, 1, 0}, in);
        QCOMPARE(t.distance, 2.0f);
        QVERIFY(std::abs(t.attenuation - 1.0f / 3.0f) < 1e-6f);
        QVERIFY(near(t.ambient, plain.ambient / 3.0f));
        QVERIFY(near(t.diffuse, plain.diffuse / 3.0f));
        QVERIFY(near(t.specular, plain.specular / 3.0f));
        QVERIFY(plain.specular.r > 0.1f);
        // A directional light is never attenuated, however far.
        in.lightEye = {0, 1, 0, 0};
        QCOMPARE(evaluateLighting({0, 0, -3}, {0, 1, 0}, in).attenuation, 1.0f);
        // kc = 0 with the light on the point: bright, not infinite.
        in.lightEye = {0, 0, -3, 1};
        in.attenuation = {0.0f, 1.0f, 0.0f};
        QVERIFY(std::isfinite(evaluateLighting({0, 0, -3}, {0, 1, 0}, in).attenuation));
    }

    // A spot at (0, 2, -3) pointing straight down with a 30 degree cutoff, exponent 2: a point
    // on the floor at horizontal offset x sees it at atan(x / 2) from the axis.
    void spotInsideAndOutsideTheCutoff()
    {
        LightingInputs in = inputs({0, 2, -3, 1});
        in.spotDirectionEye = {0, -1, 0};
        in.spotCosCutoff = std::cos(glm::radians(30.0f));
        in.spotExponent = 2.0f;
        const auto at = [&](float degrees) {
            const float x = 2.0f * std::tan(glm::radians(degrees));
            return evaluateLighting({x, 0, -3}, {0, 1, 0}, in);
        };
        QVERIFY(std::abs(at(0.0f).spot - 1.0f) < 1e-6f);
        const float c = std::cos(glm::radians(29.5f));
        QVERIFY(std::abs(at(29.5f).spot - c * c) < 1e-4f); // just inside: cos^2
        QVERIFY(at(29.5f).diffuse.r > 0.0f);
        const LightingTerms outside = at(30.5f); // just outside: nothing, ambient included
        QCOMPARE(outside.spot, 0.0f);
        QVERIFY(near(outside.ambient + outside.diffuse + outside.specular, glm::vec3(0.0f)));
        // Exponent 0: 1 all over the cone; cutoff 180 (cos -1): no spot at all.
        in.spotExponent = 0.0f;
        QCOMPARE(at(29.5f).spot, 1.0f);
        in.spotCosCutoff = -1.0f;
        in.spotDirectionEye = {0, 1, 0}; // pointing away: ignored without a cone
        QCOMPARE(at(60.0f).spot, 1.0f);
    }

    void switchedOffTermsAreLeftOutOfTheSum()
    {
        const LightingTerms t = evaluateLighting({0, 0, -3}, {0, 0, 1}, inputs({0, 0, 1, 0}));
        for (int mask = 0; mask < 8; ++mask) {
            const TermSwitches on{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
            LightingSum sum;
            sum.add(t, on);
            sum.add(t, on);
            QVERIFY(near(sum.ambient, on.ambient ? 2.0f * t.ambient : glm::vec3(0)));
            QVERIFY(near(sum.diffuse, on.diffuse ? 2.0f * t.diffuse : glm::vec3(0)));
            QVERIFY(near(sum.specular, on.specular ? 2.0f * t.specular : glm::vec3(0)));
        }
    }

    void baseColourModulatesAmbientAndDiffuseOnly()
    {
        const glm::vec3 c = shadedColor({0.5f, 0.4f, 0.2f}, {0.1f, 0.1f, 0.1f}, {0.5f, 1, 0});
        QVERIFY(near(c, {0.35f, 0.5f, 0.1f}));
        Material m;
        QVERIFY(near(unlitColor(m, {0.5f, 0.5f, 0.5f}), {0.5f, 0, 0}));
    }
};

QTEST_APPLESS_MAIN(TestLighting)
#include "test_lighting.moc"
