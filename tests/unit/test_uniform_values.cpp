// The values the renderer feeds each uniform of the semantic table, for both seed conventions
// (the slides' names and the exercise's), worked out here from the frames with GLM: the
// normal matrices as inverse transposes, the light brought into eye space by hand for each
// frame and w, colours of a light switched off as black.
#include "frames.h"
#include "glm_to_string.h"
#include "semantics.h"
#include "uniform_values.h"

#include <QTest>

#include <glm/gtc/epsilon.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace lb;

namespace {

bool near(const glm::vec4 &a, const glm::vec4 &b)
{
    return glm::all(glm::epsilonEqual(a, b, 1e-4f));
}

bool near(const glm::mat4 &a, const glm::mat4 &b)
{
    for (int c = 0; c < 4; ++c)
        if (!near(a[c], b[c]))
            return false;
    return true;
}

// A scene where every value differs from its neighbours: turned and squashed (so the normal
// matrix is not the model-view), a camera off the axis, four lights with their own colours.
Scene busyScene()
{
    Scene s;
    s.objects[0].rotationDegrees = {30.0f, -50.0f, 10.0f};
    s.objects[0].scale = {1.8f, 0.6f, 1.0f};
    s.camera.yawDegrees = 40.0f;
    s.camera.pitchDegrees = -15.0f;
    s.objects[0].material.ka = {0.1f, 0.2f, 0.3f};
    s.objects[0].material.kd = {0.4f, 0.5f, 0.6f};
    s.objects[0].material.ks = {0.7f, 0.8f, 0.9f};
    s.objects[0].material.shininess = 42.0f;
    for (int i = 0; i < kMaxLights; ++i) {
        Light &l = s.lights[std::size_t(i)];
        l.enabled = true;
        l.colors.ia = glm::vec3(0.01f * float(i + 1));
        l.colors.id = glm::vec3(0.1f * float(i + 1), 0.2f, 0.3f);
        l.colors.is = glm::vec3(0.9f, 0.1f * float(i + 1), 0.5f);
        l.position = {1.0f + float(i), -2.0f, 3.0f, 1.0f};
    }
    return s;
}

// busyScene() with every light given in `frame`, as a point (w = 1) or a direction (w = 0).
Scene lightsIn(LightFrame frame, float w)
{
    Scene s = busyScene();
    for (Light &l : s.lights) {
        l.frame = frame;
        l.position.w = w;
    }
    return s;
}

glm::vec4 value(const QString &name, const Scene &scene, const Frames &frames, int light = 0)
{
    const std::optional<Semantic> s = semanticOf(name);
    if (!s)
        qFatal("%s is not in the semantic table", qPrintable(name));
    return uniformValue(*s, scene, frames, light).vector;
}

glm::mat4 matrix(const QString &name, const Scene &scene, const Frames &frames)
{
    const std::optional<Semantic> s = semanticOf(name);
    if (!s)
        qFatal("%s is not in the semantic table", qPrintable(name));
    const UniformValue v = uniformValue(*s, scene, frames);
    if (!v.isMatrix)
        qFatal("%s is not a matrix", qPrintable(name));
    return v.matrix;
}

} // namespace

Q_DECLARE_METATYPE(lb::LightFrame)

class TestUniformValues : public QObject
{
    Q_OBJECT
private slots:
    void everySemanticHasANameAndEveryNameItsSemantic()
    {
        for (int i = 0; i <= int(kLastSemantic); ++i) {
            const QStringList names = allUniformNames(Semantic(i));
            QVERIFY2(!names.isEmpty(), qPrintable(QString("semantic %1 has no name").arg(i)));
            // A name of two meanings (uProjection) has each for its own declared shape.
            for (const QString &name : names) {
                const std::optional<Semantic> s{Semantic(i)};
                QVERIFY2(semanticOf(name, UniformShape::Matrix) == s ||
                             semanticOf(name, UniformShape::Number) == s ||
                             semanticOf(name, UniformShape::Sampler) == s,
                         qPrintable(name));
            }
        }
        QCOMPARE(semanticOf("uColor"), std::nullopt); // the overlays' own, a user's own
        QCOMPARE(uniformNames(Semantic::LightDiffuse), QStringList({"lightDif", "uLightColor"}));
        // Every semantic of the course has a course name (the panels' tooltips give them).
        for (int i = 0; i <= int(Semantic::Show); ++i)
            QVERIFY(!uniformNames(Semantic(i)).isEmpty());
        QVERIFY(allUniformNames(Semantic::LightDiffuse).contains("lightColor"));
        QCOMPARE(conventionOf("lightPos"), std::optional<Convention>(Convention::LearnOpenGL));
        QCOMPARE(conventionOf("mModelView"), std::optional<Convention>(Convention::Course));
        QCOMPARE(conventionOf("myOwnUniform"), std::nullopt);
    }

    // A name that means two things by its type: the course's uProjection switch (an int) and
    // the matrix of that name; LearnOpenGL's material.diffuse, a colour in the materials
    // chapter and a sampler in the lighting maps'.
    void theDeclaredTypeChoosesBetweenMeanings()
    {
        QCOMPARE(semanticOf("uProjection", UniformShape::Number),
                 std::optional<Semantic>(Semantic::ProjectionKind));
        QCOMPARE(semanticOf("uProjection", UniformShape::Matrix),
                 std::optional<Semantic>(Semantic::Projection));
        QCOMPARE(semanticOf("material.diffuse", UniformShape::Number),
                 std::optional<Semantic>(Semantic::MaterialDiffuse));
        QCOMPARE(semanticOf("material.diffuse", UniformShape::Sampler),
                 std::optional<Semantic>(Semantic::Sampler));
        // A name declared with a shape it never has feeds nothing rather than garbage.
        QCOMPARE(semanticOf("lightPos", UniformShape::Matrix), std::nullopt);
        QCOMPARE(semanticOf("model", UniformShape::Number), std::nullopt);
    }

    // The tutorials' matrices: model (world from object), its inverse transpose, the products.
    void tutorialMatrices_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("which"); // 0 model, 1 its normals, 2 P*V, 3 P*MV, 4 MV, 5 V, 6 P
        QTest::newRow("LearnOpenGL model") << "model" << 0;
        QTest::newRow("LearnOpenGL view") << "view" << 5;
        QTest::newRow("LearnOpenGL projection") << "projection" << 6;
        QTest::newRow("webglfundamentals u_world") << "u_world" << 0;
        QTest::newRow("webglfundamentals u_worldInverseTranspose")
            << "u_worldInverseTranspose" << 1;
        QTest::newRow("webglfundamentals u_viewProjection") << "u_viewProjection" << 2;
        QTest::newRow("webglfundamentals u_worldViewProjection") << "u_worldViewProjection" << 3;
        QTest::newRow("Angel modelViewMatrix") << "modelViewMatrix" << 4;
        QTest::newRow("three.js modelMatrix") << "modelMatrix" << 0;
        QTest::newRow("three.js viewMatrix") << "viewMatrix" << 5;
        QTest::newRow("Cookbook MVP") << "MVP" << 3;
        QTest::newRow("Cookbook ModelViewMatrix") << "ModelViewMatrix" << 4;
        QTest::newRow("glslViewer u_modelViewProjectionMatrix")
            << "u_modelViewProjectionMatrix" << 3;
    }
    void tutorialMatrices()
    {
        QFETCH(QString, name);
        QFETCH(int, which);
        const Scene scene = busyScene();
        const Frames f = computeFrames(scene, 1.5f);
        const glm::mat4 model = modelMatrix(scene.objects[0]);
        const glm::mat4 expected[7] = {model,
                                       glm::inverseTranspose(model),
                                       f.projection * f.view,
                                       f.projection * f.view * model,
                                       f.view * model,
                                       f.view,
                                       f.projection};
        QVERIFY2(near(matrix(name, scene, f), expected[which]),
                 glmText(matrix(name, scene, f)).constData());
    }

    // World-space light and camera positions (LearnOpenGL, webglfundamentals, glslViewer),
    // from a light given in each frame: the eye-space light of uLightPosition brought back
    // through the view, and the eye at the view's origin.
    void worldPositionsFromEveryFrame_data() { lightPositionInEachFrame_data(); }
    void worldPositionsFromEveryFrame()
    {
        QFETCH(LightFrame, frame);
        QFETCH(float, w);
        const Scene scene = lightsIn(frame, w);
        const Frames f = computeFrames(scene, 1.0f);
        const glm::mat4 world = glm::inverse(f.view);
        for (int i = 0; i < kMaxLights; ++i) {
            const glm::vec4 eye = value("uLightPosition", scene, f, i);
            glm::vec4 expected = (w == 1.0f ? world : glm::inverseTranspose(world)) * eye;
            expected.w = w;
            for (const char *name : {"lightPos", "light.position", "u_lightWorldPosition"})
                QVERIFY2(near(value(name, scene, f, i), expected),
                         (glmText(value(name, scene, f, i)) + " expected " + glmText(expected))
                             .constData());
            const glm::vec3 towards = glm::normalize(glm::vec3(expected));
            QVERIFY(near(value("u_reverseLightDirection", scene, f, i), glm::vec4(towards, 0)));
            if (w == 0.0f) // a directional light shines away from where it is
                QVERIFY(near(value("light.direction", scene, f, i), glm::vec4(-towards, 0)));
            if (frame == LightFrame::World)
                QVERIFY(
                    near(value("lightPos", scene, f, i), scene.lights[std::size_t(i)].position));
        }
        const glm::vec4 camera = world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        for (const char *name : {"viewPos", "u_viewWorldPosition", "cameraPosition", "u_camera"})
            QVERIFY(near(value(name, scene, f), camera));
        QVERIFY(near(camera, glm::vec4(scene.camera.eye(), 1.0f))); // the orbit camera's eye
    }

    // Angel's products, LearnOpenGL's and the Cookbook's structs, webglfundamentals' colours.
    void tutorialColours()
    {
        Scene scene = busyScene();
        scene.lights[1].enabled = false;
        for (int i = 0; i < kMaxLights; ++i)
            scene.lights[std::size_t(i)].attenuation = {1.0f, 0.1f * float(i), 0.02f * float(i)};
        const Frames f = computeFrames(scene, 1.0f);
        const Material &m = scene.objects[0].material;
        for (int i = 0; i < kMaxLights; ++i) {
            const Light &l = scene.lights[std::size_t(i)];
            const glm::vec3 on = l.enabled ? glm::vec3(1.0f) : glm::vec3(0.0f);
            QCOMPARE(value("ambientProduct", scene, f, i), glm::vec4(l.colors.ia * m.ka * on, 1));
            QCOMPARE(value("diffuseProduct", scene, f, i), glm::vec4(l.colors.id * m.kd * on, 1));
            QCOMPARE(value("specularProduct", scene, f, i), glm::vec4(l.colors.is * m.ks * on, 1));
            for (const char *name : {"light.ambient", "Light.La"})
                QCOMPARE(value(name, scene, f, i), glm::vec4(l.colors.ia * on, 1));
            for (const char *name :
                 {"lightColor", "light.diffuse", "u_lightColor", "Light.Ld", "Light.L"})
                QCOMPARE(value(name, scene, f, i), glm::vec4(l.colors.id * on, 1));
            for (const char *name : {"light.specular", "u_specularColor", "Light.Ls"})
                QCOMPARE(value(name, scene, f, i), glm::vec4(l.colors.is * on, 1));
            QCOMPARE(value("light.constant", scene, f, i).x, l.attenuation.x);
            QCOMPARE(value("light.linear", scene, f, i).x, l.attenuation.y);
            QCOMPARE(value("light.quadratic", scene, f, i).x, l.attenuation.z);
            QVERIFY(isPerLight(*semanticOf("ambientProduct")));
        }
        for (const char *name : {"objectColor", "u_color", "material.diffuse", "Material.Kd"})
            QCOMPARE(value(name, scene, f), glm::vec4(m.kd, 1.0f));
        for (const char *name : {"material.ambient", "Material.Ka"})
            QCOMPARE(value(name, scene, f), glm::vec4(m.ka, 1.0f));
        for (const char *name : {"material.specular", "Material.Ks"})
            QCOMPARE(value(name, scene, f), glm::vec4(m.ks, 1.0f));
        for (const char *name : {"material.shininess", "u_shininess", "Material.Shininess"})
            QCOMPARE(value(name, scene, f).x, m.shininess);
    }

    // What a control a tutorial's name reads is shown as used for.
    void tutorialNamesCountAsReadingThePanels()
    {
        const auto has = [](Semantic derived, Semantic control) {
            const std::vector<Semantic> c = controlledBy(derived);
            return std::find(c.begin(), c.end(), control) != c.end();
        };
        QVERIFY(has(Semantic::AmbientProduct, Semantic::LightAmbient));
        QVERIFY(has(Semantic::AmbientProduct, Semantic::MaterialAmbient));
        QVERIFY(has(Semantic::LightPositionWorld, Semantic::LightPositionEye));
        QVERIFY(has(Semantic::AttenuationLinear, Semantic::LightAttenuation));
        QVERIFY(has(Semantic::ModelViewProjection, Semantic::Projection));
        QVERIFY(has(Semantic::Shininess, Semantic::Shininess));
    }

    void matricesInBothConventions_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("which"); // 0 model-view, 1 normals, 2 view, 3 view normals, 4 P
        QTest::newRow("slides mModelView") << "mModelView" << 0;
        QTest::newRow("slides mNormals") << "mNormals" << 1;
        QTest::newRow("slides mView") << "mView" << 2;
        QTest::newRow("slides mViewNormals") << "mViewNormals" << 3;
        QTest::newRow("slides mProjection") << "mProjection" << 4;
        QTest::newRow("exercise uModelViewMatrix") << "uModelViewMatrix" << 0;
        QTest::newRow("exercise uNormalMatrix") << "uNormalMatrix" << 1;
        QTest::newRow("exercise uProjectionMatrix") << "uProjectionMatrix" << 4;
    }
    void matricesInBothConventions()
    {
        QFETCH(QString, name);
        QFETCH(int, which);
        for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
            Scene scene = busyScene();
            scene.shading.projection = projection;
            const Frames f = computeFrames(scene, 1.5f);
            const glm::mat4 expected[5] = {f.view * f.model, glm::inverseTranspose(f.modelView),
                                           f.view, glm::inverseTranspose(f.view), f.projection};
            QVERIFY2(near(matrix(name, scene, f), expected[which]),
                     glmText(matrix(name, scene, f)).constData());
        }
        // The wrong normal matrix on purpose: the model-view itself.
        Scene wrong = busyScene();
        wrong.shading.normalsByModelView = true;
        const Frames f = computeFrames(wrong, 1.5f);
        if (which == 1)
            QVERIFY(near(matrix(name, wrong, f), f.modelView));
    }

    void lightPositionInEachFrame_data()
    {
        QTest::addColumn<LightFrame>("frame");
        QTest::addColumn<float>("w");
        for (LightFrame frame : {LightFrame::Camera, LightFrame::World, LightFrame::Object})
            for (float w : {0.0f, 1.0f})
                QTest::newRow(qPrintable(QString("%1, w = %2").arg(toName(frame)).arg(w)))
                    << frame << w;
    }
    void lightPositionInEachFrame()
    {
        QFETCH(LightFrame, frame);
        QFETCH(float, w);
        const Scene scene = lightsIn(frame, w);
        const Frames f = computeFrames(scene, 1.0f);
        // Points by the frame's matrix, directions by its inverse transpose.
        const glm::mat4 toEye = frame == LightFrame::Camera  ? glm::mat4(1.0f)
                                : frame == LightFrame::World ? f.view
                                                             : f.view * f.model;
        for (int i = 0; i < kMaxLights; ++i) {
            const glm::vec4 given = scene.lights[std::size_t(i)].position;
            glm::vec4 eye = (w == 1.0f ? toEye : glm::inverseTranspose(toEye)) * given;
            eye.w = w; // the inverse transpose puts the translation into w: a direction keeps 0
            // The slides' lightPosition goes as given (the shader moves it); the exercise's
            // uLightPosition arrives in camera coordinates.
            QCOMPARE(value("lightPosition", scene, f, i), given);
            QVERIFY2(near(value("uLightPosition", scene, f, i), eye),
                     (glmText(value("uLightPosition", scene, f, i)) + " expected " + glmText(eye))
                         .constData());
            QCOMPARE(value("uLightFrame", scene, f, i).x, float(int(frame)));
        }
    }

    void lightColoursAndSwitches()
    {
        Scene scene = busyScene();
        scene.lights[2].enabled = false;
        const Frames f = computeFrames(scene, 1.0f);
        for (int i = 0; i < kMaxLights; ++i) {
            const Light &l = scene.lights[std::size_t(i)];
            const glm::vec3 on = l.enabled ? glm::vec3(1.0f) : glm::vec3(0.0f);
            QCOMPARE(value("lightAmb", scene, f, i), glm::vec4(l.colors.ia * on, 1.0f));
            QCOMPARE(value("lightDif", scene, f, i), glm::vec4(l.colors.id * on, 1.0f));
            QCOMPARE(value("uLightColor", scene, f, i), glm::vec4(l.colors.id * on, 1.0f));
            QCOMPARE(value("lightSpe", scene, f, i), glm::vec4(l.colors.is * on, 1.0f));
            QCOMPARE(value("uLightEnabled", scene, f, i).x, l.enabled ? 1.0f : 0.0f);
        }
        for (const QString &name : {QString("lightAmb"), QString("uLightPosition")})
            QVERIFY(isPerLight(*semanticOf(name)));
        QVERIFY(!isPerLight(Semantic::MaterialDiffuse));
    }

    void materialAndShadingSwitches()
    {
        Scene scene = busyScene();
        const Frames f = computeFrames(scene, 1.0f);
        QCOMPARE(value("materialAmb", scene, f), glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
        QCOMPARE(value("materialDif", scene, f), glm::vec4(0.4f, 0.5f, 0.6f, 1.0f));
        QCOMPARE(value("materialSpe", scene, f), glm::vec4(0.7f, 0.8f, 0.9f, 1.0f));
        QCOMPARE(value("shininess", scene, f).x, 42.0f);
        QCOMPARE(value("uSampler", scene, f).x, 0.0f);
        for (bool on : {false, true}) {
            scene.shading.specular = on ? SpecularModel::Blinn : SpecularModel::Phong;
            scene.shading.projection = on ? Projection::Orthographic : Projection::Perspective;
            scene.shading.lighting = on;
            scene.shading.vertexColors = on;
            scene.objects[0].texture = on;
            const float x = on ? 1.0f : 0.0f;
            for (const char *name : {"uSpecularModel", "uProjection", "uEnableLighting",
                                     "uEnableVertexColor", "uEnableTexture"})
                QCOMPARE(value(name, scene, f).x, x);
        }
        for (int show = 0; show <= int(ShowChoice::Attenuation); ++show) {
            scene.shading.show = ShowChoice(show);
            QCOMPARE(value("uShow", scene, f).x, float(show));
        }
        // Each term alone.
        for (int term = 0; term < 3; ++term) {
            scene.shading.terms = {term == 0, term == 1, term == 2};
            QCOMPARE(value("uEnableAmbient", scene, f).x, term == 0 ? 1.0f : 0.0f);
            QCOMPARE(value("uEnableDiffuse", scene, f).x, term == 1 ? 1.0f : 0.0f);
            QCOMPARE(value("uEnableSpecular", scene, f).x, term == 2 ? 1.0f : 0.0f);
        }
    }

    // Attenuation and spot go to the shaders per light, as given in the panel (the direction
    // in the light's own frame, like lightPosition); the cosine of 180 degrees is exactly -1.
    void attenuationAndSpotPerLight()
    {
        Scene scene = busyScene();
        for (int i = 0; i < kMaxLights; ++i) {
            Light &l = scene.lights[std::size_t(i)];
            l.attenuation = {1.0f, 0.1f * float(i), 0.01f * float(i)};
            l.spot = {{0.0f, -1.0f, float(i)}, 10.0f * float(i + 1), float(i)};
        }
        scene.lights[3].spot.cutoffDegrees = 180.0f;
        const Frames f = computeFrames(scene, 1.0f);
        for (int i = 0; i < kMaxLights; ++i) {
            const float k = float(i);
            QCOMPARE(value("lightAttenuation", scene, f, i),
                     glm::vec4(1.0f, 0.1f * k, 0.01f * k, 0.0f));
            QCOMPARE(value("spotDirection", scene, f, i), glm::vec4(0.0f, -1.0f, k, 0.0f));
            QCOMPARE(value("spotExponent", scene, f, i).x, k);
        }
        QCOMPARE(value("spotCutoff", scene, f, 1).x, 20.0f);
        QCOMPARE(value("spotCosCutoff", scene, f, 1).x, std::cos(glm::radians(20.0f)));
        QCOMPARE(value("spotCutoff", scene, f, 3).x, 180.0f);
        QCOMPARE(value("spotCosCutoff", scene, f, 3).x, -1.0f);
        QVERIFY(isPerLight(*semanticOf("spotCosCutoff")));
        QVERIFY(isPerLight(*semanticOf("lightAttenuation")));
    }
};

QTEST_GUILESS_MAIN(TestUniformValues)
#include "test_uniform_values.moc"
