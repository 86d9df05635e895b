// The matrices of each frame and the light brought into eye space.
#include "frames.h"

#include <QTest>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/epsilon.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <random>

using namespace lb;

Q_DECLARE_METATYPE(glm::vec4)
Q_DECLARE_METATYPE(lb::Projection)

namespace {
bool near(const glm::vec4 &a, const glm::vec4 &b, float eps = 1e-4f)
{
    return glm::all(glm::epsilonEqual(a, b, eps));
}

// A camera on +Z looking at the origin: mView is a translation by -distance along Z.
Scene straightOnScene()
{
    Scene s;
    s.camera.yawDegrees = 0;
    s.camera.pitchDegrees = 0;
    s.camera.distance = 4;
    return s;
}
} // namespace

class TestFrames : public QObject
{
    Q_OBJECT
private slots:
    void normalMatrixOnRandomNonUniformTransforms()
    {
        std::mt19937 rng(1234);
        std::uniform_real_distribution<float> angle(-180, 180), scale(0.2f, 3.0f), unit(-1, 1);
        for (int i = 0; i < 200; ++i) {
            Scene s;
            s.objects[0].rotationDegrees = {angle(rng), angle(rng), angle(rng)};
            s.objects[0].scale = {scale(rng), scale(rng), scale(rng)};
            s.camera.yawDegrees = angle(rng);
            s.camera.pitchDegrees = angle(rng) / 3;
            const Frames f = computeFrames(s, 1.5f);
            const glm::mat4 expected = glm::inverseTranspose(f.modelView);
            for (int c = 0; c < 4; ++c)
                QVERIFY(near(f.normals[c], expected[c]));
            // What the normal matrix is for: a tangent moved by mModelView stays perpendicular
            // to the normal moved by mNormals. mModelView itself would break this.
            const glm::vec3 n = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
            const glm::vec3 t = glm::normalize(glm::cross(n, glm::vec3(0.3f, 0.5f, 0.8f)));
            const glm::vec3 tEye = glm::vec3(f.modelView * glm::vec4(t, 0));
            const glm::vec3 nEye = glm::vec3(f.normals * glm::vec4(n, 0));
            QVERIFY(std::abs(glm::dot(glm::normalize(tEye), glm::normalize(nEye))) < 1e-4f);
        }
    }

    void normalMatrixIsNotTheModelViewUnderNonUniformScale()
    {
        Scene s;
        s.objects[0].scale = {3, 1, 1};
        s.objects[0].rotationDegrees = {0, 0, 30};
        const Frames f = computeFrames(s, 1);
        const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
        const glm::vec3 wrong = glm::normalize(glm::vec3(f.modelView * glm::vec4(n, 0)));
        const glm::vec3 right = glm::normalize(glm::vec3(f.normals * glm::vec4(n, 0)));
        QVERIFY(glm::dot(wrong, right) < 0.95f);
    }

    // Dragging a tenth of the view's height moves the picture a tenth of its height, in wide
    // and narrow views alike (the point under the cursor stays under it).
    void panFollowsTheCursorInAnyAspect()
    {
        for (float aspect : {0.4f, 1.0f, 2.0f}) {
            OrbitCamera camera;
            const glm::vec3 before = camera.target;
            camera.pan(0.0f, 0.1f, aspect);
            const glm::vec4 clip = camera.projection(aspect, Projection::Perspective) *
                                   camera.view() * glm::vec4(before, 1.0f);
            QVERIFY2(std::abs(clip.y / clip.w + 0.2f) < 1e-3f,
                     qPrintable(QString("aspect %1: %2").arg(aspect).arg(clip.y / clip.w)));
        }
    }

    void viewMatrixOfTheOrbitCamera()
    {
        const Frames f = computeFrames(straightOnScene(), 1);
        QVERIFY(near(f.view * glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, -4, 1)));
        QVERIFY(near(f.view * glm::vec4(1, 2, 3, 1), glm::vec4(1, 2, -1, 1)));
    }

    // A narrow view (a side-by-side half at 1024x768) frames what a square one frames across
    // its width; a wide view keeps the vertical field. Both projections.
    void narrowViewsKeepTheSquareViewsWidth_data()
    {
        QTest::addColumn<Projection>("kind");
        QTest::newRow("perspective") << Projection::Perspective;
        QTest::newRow("orthographic") << Projection::Orthographic;
    }
    void narrowViewsKeepTheSquareViewsWidth()
    {
        QFETCH(Projection, kind);
        const OrbitCamera camera;
        const glm::mat4 square = camera.projection(1.0f, kind);
        for (float aspect : {0.3f, 0.5f, 0.8f})
            QVERIFY2(std::abs(camera.projection(aspect, kind)[0][0] - square[0][0]) < 1e-5f,
                     qPrintable(QString("aspect %1").arg(aspect)));
        // Wide: the height is kept, so x scales with 1/aspect.
        QVERIFY(std::abs(camera.projection(2.0f, kind)[1][1] - square[1][1]) < 1e-5f);
        QVERIFY(std::abs(camera.projection(2.0f, kind)[0][0] - square[0][0] / 2.0f) < 1e-5f);
    }
    void lightInEye_data()
    {
        QTest::addColumn<int>("frame");
        QTest::addColumn<glm::vec4>("light");
        QTest::addColumn<glm::vec4>("expected");
        // Camera on +Z at distance 4, model turned 90 degrees about Y and scaled 2x along X.
        QTest::newRow("camera point")
            << int(LightFrame::Camera) << glm::vec4(1, 2, 3, 1) << glm::vec4(1, 2, 3, 1);
        QTest::newRow("camera direction")
            << int(LightFrame::Camera) << glm::vec4(0, 1, 0, 0) << glm::vec4(0, 1, 0, 0);
        // World: the slides' light (0, 1.8, 1.3) seen from (0, 0, 4).
        QTest::newRow("world point") << int(LightFrame::World) << glm::vec4(0, 1.8f, 1.3f, 1)
                                     << glm::vec4(0, 1.8f, -2.7f, 1);
        QTest::newRow("world direction")
            << int(LightFrame::World) << glm::vec4(0, 1, 1, 0) << glm::vec4(0, 1, 1, 0);
        // Object: x of the object points along -Z of the world after the turn, and is doubled.
        QTest::newRow("object point")
            << int(LightFrame::Object) << glm::vec4(1, 0, 0, 1) << glm::vec4(0, 0, -6, 1);
        // A direction goes by the inverse transpose: the 2x scale halves it along that axis.
        QTest::newRow("object direction")
            << int(LightFrame::Object) << glm::vec4(1, 0, 0, 0) << glm::vec4(0, 0, -0.5f, 0);
    }

    void lightInEye()
    {
        QFETCH(int, frame);
        QFETCH(glm::vec4, light);
        QFETCH(glm::vec4, expected);
        Scene s = straightOnScene();
        s.objects[0].rotationDegrees = {0, 90, 0};
        s.objects[0].scale = {2, 1, 1};
        const Frames f = computeFrames(s, 1);
        const glm::vec4 eye = lb::lightInEye(f, 0, light, LightFrame(frame));
        if (!near(eye, expected))
            QFAIL(qPrintable(
                QString("got (%1, %2, %3, %4)").arg(eye.x).arg(eye.y).arg(eye.z).arg(eye.w)));
        // And back, as the probe shows P and L in the light's frame.
        QVERIFY(near(eyeToFrame(f, 0, eye, LightFrame(frame)), light));
    }

    void worldLightStaysInTheSceneWhenTheCameraOrbits()
    {
        // Orbiting moves a world light in eye space, but not a camera light.
        Scene a = straightOnScene(), b = straightOnScene();
        b.camera.orbit(90, 0);
        const glm::vec4 light(0, 1.8f, 1.3f, 1);
        const Frames fa = computeFrames(a, 1), fb = computeFrames(b, 1);
        QVERIFY(!near(lb::lightInEye(fa, 0, light, LightFrame::World),
                      lb::lightInEye(fb, 0, light, LightFrame::World)));
        QVERIFY(near(lb::lightInEye(fa, 0, light, LightFrame::Camera),
                     lb::lightInEye(fb, 0, light, LightFrame::Camera)));
        // ... and the world light keeps its distance to the world origin.
        const float da = glm::length(glm::vec3(lb::lightInEye(fa, 0, light, LightFrame::World)) -
                                     glm::vec3(fa.view[3]));
        const float db = glm::length(glm::vec3(lb::lightInEye(fb, 0, light, LightFrame::World)) -
                                     glm::vec3(fb.view[3]));
        QVERIFY(std::abs(da - db) < 1e-4f);
    }

    void objectLightTurnsWithTheModel()
    {
        Scene a = straightOnScene(), b = straightOnScene();
        b.objects[0].rotationDegrees.y = 90;
        const glm::vec4 light(0, 0, 2, 1);
        const glm::vec4 ea = lb::lightInEye(computeFrames(a, 1), 0, light, LightFrame::Object);
        const glm::vec4 eb = lb::lightInEye(computeFrames(b, 1), 0, light, LightFrame::Object);
        QVERIFY(near(ea, glm::vec4(0, 0, -2, 1)));
        QVERIFY(near(eb, glm::vec4(2, 0, -4, 1)));
    }
};

QTEST_APPLESS_MAIN(TestFrames)
#include "test_frames.moc"
