// Programs written in the names of each tutorial and book students paste from (LearnOpenGL,
// webglfundamentals, Angel's textbook, three.js, the GLSL Cookbook, glslViewer) and in names of
// no convention draw what the model says without an edit: every uniform they declare is fed
// (semantics.h), every attribute reaches its slot by name, by what the name says or by
// layout(location = N), and the pixels agree with the CPU reference. The samples are this
// test's own, written in each convention's style and names, computing the course's model.
#include "program.h"
#include "reference_compare.h"
#include "webgl1_translation.h"

#include <QGuiApplication>
#include <QRegularExpression>
#include <QTest>

using namespace lb;
using namespace lb::test;

namespace {

// LearnOpenGL's Materials chapter: world space, the Material and Light structs, Phong's R.V.
const char *kLearnOpenGlVertex = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 FragPos;
out vec3 Normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(model))) * aNormal;
    gl_Position = projection * view * vec4(FragPos, 1.0);
}
)";
const char *kLearnOpenGlMaterialsFragment = R"(#version 330 core
out vec4 FragColor;

struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
};

struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

in vec3 FragPos;
in vec3 Normal;

uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    vec3 ambient = light.ambient * material.ambient;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(light.position - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * (diff * material.diffuse);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = diff > 0.0 ? pow(max(dot(viewDir, reflectDir), 0.0), material.shininess) : 0.0;
    vec3 specular = light.specular * (spec * material.specular);
    FragColor = vec4(ambient + diffuse + specular, 1.0);
}
)";
// LearnOpenGL's Basic Lighting: one light colour, the object's colour, fixed strengths.
const char *kLearnOpenGlBasicFragment = R"(#version 330 core
out vec4 FragColor;

in vec3 Normal;
in vec3 FragPos;

uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    float ambientStrength = 0.1;
    vec3 ambient = ambientStrength * lightColor;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;

    float specularStrength = 0.5;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 specular = specularStrength * spec * lightColor;

    vec3 result = (ambient + diffuse + specular) * objectColor;
    FragColor = vec4(result, 1.0);
}
)";

// webglfundamentals' point light with a specular highlight (WebGL 1, the half vector).
const char *kWebGlFundamentalsVertex = R"(attribute vec4 a_position;
attribute vec3 a_normal;

uniform vec3 u_lightWorldPosition;
uniform vec3 u_viewWorldPosition;

uniform mat4 u_world;
uniform mat4 u_worldViewProjection;
uniform mat4 u_worldInverseTranspose;

varying vec3 v_normal;
varying vec3 v_surfaceToLight;
varying vec3 v_surfaceToView;

void main() {
  gl_Position = u_worldViewProjection * a_position;
  v_normal = mat3(u_worldInverseTranspose) * a_normal;
  vec3 surfaceWorldPosition = (u_world * a_position).xyz;
  v_surfaceToLight = u_lightWorldPosition - surfaceWorldPosition;
  v_surfaceToView = u_viewWorldPosition - surfaceWorldPosition;
}
)";
const char *kWebGlFundamentalsFragment = R"(precision mediump float;

varying vec3 v_normal;
varying vec3 v_surfaceToLight;
varying vec3 v_surfaceToView;

uniform vec4 u_color;
uniform float u_shininess;
uniform vec3 u_lightColor;
uniform vec3 u_specularColor;

void main() {
  vec3 normal = normalize(v_normal);
  vec3 surfaceToLightDirection = normalize(v_surfaceToLight);
  vec3 surfaceToViewDirection = normalize(v_surfaceToView);
  vec3 halfVector = normalize(surfaceToLightDirection + surfaceToViewDirection);

  float light = dot(normal, surfaceToLightDirection);
  float specular = 0.0;
  if (light > 0.0) {
    specular = pow(dot(normal, halfVector), u_shininess);
  }

  gl_FragColor = u_color;
  gl_FragColor.rgb *= light * u_lightColor;
  gl_FragColor.rgb += specular * u_specularColor;
}
)";

// Angel's textbook (MV.js): eye space, the products of the light's and material's colours,
// a mat3 normal matrix; per fragment.
const char *kAngelVertex = R"(attribute vec4 vPosition;
attribute vec4 vNormal;
varying vec3 N, L, E;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform vec4 lightPosition;
uniform mat3 normalMatrix;

void main()
{
    vec3 pos = (modelViewMatrix * vPosition).xyz;
    if (lightPosition.w == 0.0) L = lightPosition.xyz;
    else L = lightPosition.xyz - pos;
    E = -pos;
    N = normalMatrix * vNormal.xyz;
    gl_Position = projectionMatrix * modelViewMatrix * vPosition;
}
)";
const char *kAngelFragment = R"(precision mediump float;
uniform vec4 ambientProduct;
uniform vec4 diffuseProduct;
uniform vec4 specularProduct;
uniform float shininess;
varying vec3 N, L, E;

void main()
{
    vec3 NN = normalize(N);
    vec3 LL = normalize(L);
    vec3 EE = normalize(E);
    vec3 H = normalize(LL + EE);
    vec4 ambient = ambientProduct;
    float Kd = max(dot(LL, NN), 0.0);
    vec4 diffuse = Kd * diffuseProduct;
    float Ks = pow(max(dot(NN, H), 0.0), shininess);
    vec4 specular = Ks * specularProduct;
    if (dot(LL, NN) < 0.0) specular = vec4(0.0, 0.0, 0.0, 1.0);
    gl_FragColor = ambient + diffuse + specular;
    gl_FragColor.a = 1.0;
}
)";

// three.js's RawShaderMaterial (GLSL ES 3.00): its built-in matrices and its materials' colour
// names (diffuse, specular, shininess, ambientLightColor); the light's position given in world
// coordinates and carried into eye space with viewMatrix.
const char *kThreeJsVertex = R"(#version 300 es
precision highp float;
in vec3 position;
in vec3 normal;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform mat4 viewMatrix;
uniform mat3 normalMatrix;
uniform vec3 lightPos;
out vec3 vNormalEye;
out vec3 vToLight;
out vec3 vToEye;
void main() {
    vec4 eye = modelViewMatrix * vec4(position, 1.0);
    vNormalEye = normalMatrix * normal;
    vToLight = (viewMatrix * vec4(lightPos, 1.0)).xyz - eye.xyz;
    vToEye = -eye.xyz;
    gl_Position = projectionMatrix * eye;
}
)";
const char *kThreeJsFragment = R"(#version 300 es
precision highp float;
uniform vec3 diffuse;
uniform vec3 specular;
uniform float shininess;
uniform vec3 ambientLightColor;
uniform vec3 lightColor;
in vec3 vNormalEye;
in vec3 vToLight;
in vec3 vToEye;
out vec4 outColor;
void main() {
    vec3 n = normalize(vNormalEye);
    vec3 l = normalize(vToLight);
    vec3 v = normalize(vToEye);
    float nl = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float s = nl > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    outColor = vec4(ambientLightColor * diffuse + lightColor * (nl * diffuse + s * specular), 1.0);
}
)";

// The OpenGL 4 Shading Language Cookbook's Phong model, as in its third edition: eye space,
// the LightInfo and MaterialInfo structs, one L for the diffuse and specular light.
const char *kCookbookVertex = R"(#version 330
layout (location = 0) in vec3 VertexPosition;
layout (location = 1) in vec3 VertexNormal;

out vec3 Position;
out vec3 Normal;

uniform mat4 ModelViewMatrix;
uniform mat3 NormalMatrix;
uniform mat4 ProjectionMatrix;
uniform mat4 MVP;

void main()
{
    Normal = NormalMatrix * VertexNormal;
    Position = (ModelViewMatrix * vec4(VertexPosition, 1.0)).xyz;
    gl_Position = MVP * vec4(VertexPosition, 1.0);
}
)";
const char *kCookbookFragment = R"(#version 330
in vec3 Position;
in vec3 Normal;

uniform struct LightInfo {
    vec4 Position;
    vec3 La;
    vec3 L;
} Light;

uniform struct MaterialInfo {
    vec3 Ka;
    vec3 Kd;
    vec3 Ks;
    float Shininess;
} Material;

layout (location = 0) out vec4 FragColor;

vec3 phongModel(vec3 position, vec3 n)
{
    vec3 ambient = Light.La * Material.Ka;
    vec3 s = normalize(Light.Position.xyz - position);
    float sDotN = max(dot(s, n), 0.0);
    vec3 diffuse = Material.Kd * sDotN;
    vec3 spec = vec3(0.0);
    if (sDotN > 0.0) {
        vec3 v = normalize(-position.xyz);
        vec3 r = reflect(-s, n);
        spec = Material.Ks * pow(max(dot(r, v), 0.0), Material.Shininess);
    }
    return ambient + Light.L * (diffuse + spec);
}

void main()
{
    FragColor = vec4(phongModel(Position, normalize(Normal)), 1.0);
}
)";

// GLSL 1.20 with the fixed-function pipeline's built-ins, per fragment: eye space, the
// light's products with the material, ftransform().
const char *kFixedFunctionVertex = R"(#version 120
varying vec3 eyeNormal;
varying vec3 eyePosition;
void main()
{
    eyePosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    eyeNormal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
)";
const char *kFixedFunctionFragment = R"(#version 120
varying vec3 eyeNormal;
varying vec3 eyePosition;
void main()
{
    vec3 n = normalize(eyeNormal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - eyePosition);
    float nDotL = max(dot(n, l), 0.0);
    vec4 colour = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].ambient +
                  gl_FrontLightProduct[0].diffuse * nDotL;
    if (nDotL > 0.0) {
        vec3 r = reflect(-l, n);
        float rDotV = max(dot(r, normalize(-eyePosition)), 0.0);
        colour += gl_FrontLightProduct[0].specular * pow(rDotV, gl_FrontMaterial.shininess);
    }
    gl_FragColor = colour;
}
)";
// GLSL 1.10 without #version, per vertex: a directional light, Blinn-Phong with the light's
// half vector (the viewer far along +z: the model's H under a parallel projection), the
// colour through gl_FrontColor to the fragment's gl_Color.
const char *kFixedFunctionGouraudVertex = R"(void main()
{
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float nDotL = max(dot(n, l), 0.0);
    vec4 c = gl_LightSource[0].ambient * gl_FrontMaterial.ambient +
             gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse * nDotL;
    if (nDotL > 0.0) {
        float nDotH = max(dot(n, normalize(gl_LightSource[0].halfVector.xyz)), 0.0);
        c += gl_LightSource[0].specular * gl_FrontMaterial.specular *
             pow(nDotH, gl_FrontMaterial.shininess);
    }
    gl_FrontColor = c;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";
const char *kFixedFunctionGouraudFragment = "void main() { gl_FragColor = gl_Color; }\n";

// glslViewer's names: world space, the light and the camera as positions; Lambert only.
const char *kGlslViewerVertex = R"(#ifdef GL_ES
precision mediump float;
#endif
uniform mat4 u_modelViewProjectionMatrix;
uniform mat4 u_modelMatrix;
attribute vec4 a_position;
attribute vec3 a_normal;
varying vec4 v_position;
varying vec3 v_normal;
void main(void) {
    v_position = u_modelMatrix * a_position;
    v_normal = (u_modelMatrix * vec4(a_normal, 0.0)).xyz;
    gl_Position = u_modelViewProjectionMatrix * a_position;
}
)";
const char *kGlslViewerFragment = R"(#ifdef GL_ES
precision mediump float;
#endif
uniform vec3 u_light;
uniform vec3 u_lightColor;
varying vec4 v_position;
varying vec3 v_normal;
void main(void) {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(u_light - v_position.xyz);
    gl_FragColor = vec4(u_lightColor * max(dot(n, l), 0.0), 1.0);
}
)";

// The course's uniforms with attributes of no convention: bound by what their names say, or by
// layout(location = N).
const char *kOwnNamesVertex = R"(attribute vec4 inVertexPos;
attribute vec3 inVertexNormal;
uniform mat4 mModelView;
uniform mat4 mNormals;
uniform mat4 mProjection;
varying vec3 fNormal;
varying vec3 fPosition;
void main() {
    fPosition = (mModelView * inVertexPos).xyz;
    fNormal = (mNormals * vec4(inVertexNormal, 0.0)).xyz;
    gl_Position = mProjection * mModelView * inVertexPos;
}
)";
const char *kLocationsVertex = R"(#version 330 core
layout(location = 1) in vec3 n;
layout(location = 0) in vec3 p;
uniform mat4 mModelView;
uniform mat4 mNormals;
uniform mat4 mProjection;
out vec3 fNormal;
out vec3 fPosition;
void main() {
    fPosition = (mModelView * vec4(p, 1.0)).xyz;
    fNormal = (mNormals * vec4(n, 0.0)).xyz;
    gl_Position = mProjection * mModelView * vec4(p, 1.0);
}
)";
// The course's diffuse term in camera coordinates, for both vertex shaders above.
const char *kCourseDiffuseFragment = R"(precision highp float;
uniform vec4 uLightPosition;
uniform vec3 lightDif;
uniform vec3 materialDif;
varying vec3 fNormal;
varying vec3 fPosition;
void main() {
    vec3 L = normalize(uLightPosition.xyz - fPosition);
    gl_FragColor = vec4(lightDif * materialDif * max(dot(normalize(fNormal), L), 0.0), 1.0);
}
)";
const char *kCourseDiffuseFragment330 = R"(#version 330 core
uniform vec4 uLightPosition;
uniform vec3 lightDif;
uniform vec3 materialDif;
in vec3 fNormal;
in vec3 fPosition;
out vec4 colour;
void main() {
    vec3 L = normalize(uLightPosition.xyz - fPosition);
    colour = vec4(lightDif * materialDif * max(dot(normalize(fNormal), L), 0.0), 1.0);
}
)";

Scene lightIn(Scene s, LightFrame frame)
{
    s.shading.shading = Shading::Phong;
    s.lights[0].frame = frame;
    s.lights[0].position = frame == LightFrame::Camera ? glm::vec4(1.5f, 2.0f, 2.5f, 1.0f)
                                                       : glm::vec4(0.5f, 2.5f, 2.0f, 1.0f);
    return s;
}

// The scene whose panels give the program's fixed numbers the same values: LearnOpenGL's
// Basic Lighting (ambient 0.1 of the light, specular 0.5 of it, shininess 32, all times the
// object's colour).
Scene basicLightingScene(Scene s)
{
    const glm::vec3 object(1.0f, 0.5f, 0.31f), light(1.0f);
    s.lights[0].colors = {0.1f * light, light, light};
    Material &m = s.objects[0].material;
    m.ka = object;
    m.kd = object;
    m.ks = 0.5f * object;
    m.shininess = 32.0f;
    s.shading.specular = SpecularModel::Phong;
    return s;
}

} // namespace

Q_DECLARE_METATYPE(lb::Scene)

class TestShaderConventions : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void cleanup() { m_offscreen.useProgram({}, {}); }

    void drawsAsPasted_data()
    {
        QTest::addColumn<QString>("vertex");
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<Scene>("scene");
        QTest::addColumn<int>("minSpecular");
        QTest::addColumn<int>("tolerance");
        for (LightFrame frame : {LightFrame::World, LightFrame::Camera, LightFrame::Object}) {
            Scene s = lightIn(testScene(), frame);
            s.shading.specular = SpecularModel::Phong;
            QTest::addRow("LearnOpenGL materials, light in %s", qPrintable(toName(frame)))
                << kLearnOpenGlVertex << kLearnOpenGlMaterialsFragment << s << 5 << kTolerance;
        }
        QTest::newRow("LearnOpenGL basic lighting")
            << kLearnOpenGlVertex << kLearnOpenGlBasicFragment
            << basicLightingScene(lightIn(testScene(), LightFrame::World)) << 5 << kTolerance;
        {
            // No ambient term: the specular colour alone is the light's (Ks = 1).
            Scene s = lightIn(testScene(), LightFrame::Object);
            s.lights[0].colors.ia = glm::vec3(0.0f);
            s.objects[0].material.ks = glm::vec3(1.0f);
            s.shading.specular = SpecularModel::Blinn;
            // mediump in GLSL ES: Mesa computes it at lower precision.
            QTest::newRow("webglfundamentals point light")
                << kWebGlFundamentalsVertex << kWebGlFundamentalsFragment << s << 5 << 4;
        }
        {
            Scene s = lightIn(testScene(), LightFrame::Camera);
            s.shading.specular = SpecularModel::Blinn;
            QTest::newRow("Angel, products") << kAngelVertex << kAngelFragment << s << 5 << 4;
        }
        {
            // three.js has no ambient colour of the material: its diffuse one takes the ambient
            // light; one light colour for diffuse and specular.
            Scene s = lightIn(testScene(), LightFrame::World);
            Material &m = s.objects[0].material;
            m.ka = m.kd;
            s.lights[0].colors.is = s.lights[0].colors.id;
            s.shading.specular = SpecularModel::Blinn;
            QTest::newRow("three.js raw shader")
                << kThreeJsVertex << kThreeJsFragment << s << 5 << kTolerance;
        }
        {
            Scene s = lightIn(testScene(), LightFrame::World);
            s.lights[0].colors.is = s.lights[0].colors.id; // the Cookbook's one L
            s.shading.specular = SpecularModel::Phong;
            QTest::newRow("GLSL Cookbook")
                << kCookbookVertex << kCookbookFragment << s << 5 << kTolerance;
        }
        {
            // Its normals go through the model matrix itself: a turned object, not a squashed one.
            Scene s = lightIn(testScene(), LightFrame::World);
            s.objects[0].scale = glm::vec3(1.0f);
            s.lights[0].colors.ia = glm::vec3(0.0f);
            s.objects[0].material.kd = glm::vec3(1.0f);
            s.shading.terms.specular = false;
            QTest::newRow("glslViewer, Lambert")
                << kGlslViewerVertex << kGlslViewerFragment << s << 0 << 4;
        }
        {
            Scene s = lightIn(testScene(), LightFrame::Camera);
            s.lights[0].colors.ia = glm::vec3(0.0f);
            s.shading.terms.specular = false;
            QTest::newRow("attributes named inVertexPos, inVertexNormal")
                << kOwnNamesVertex << kCourseDiffuseFragment << s << 0 << kTolerance;
            QTest::newRow("attributes p, n at layout(location = 0, 1)")
                << kLocationsVertex << kCourseDiffuseFragment330 << s << 0 << kTolerance;
        }
        {
            Scene s = lightIn(testScene(), LightFrame::Camera);
            s.shading.specular = SpecularModel::Phong;
            QTest::newRow("GLSL 1.20 built-ins, per fragment")
                << kFixedFunctionVertex << kFixedFunctionFragment << s << 5 << kTolerance;
        }
        {
            Scene s = lightIn(testScene(), LightFrame::Camera);
            s.lights[0].position.w = 0.0f;
            s.shading.shading = Shading::Gouraud;
            s.shading.specular = SpecularModel::Blinn;
            s.shading.projection = Projection::Orthographic;
            QTest::newRow("GLSL 1.10 built-ins, per vertex, half vector")
                << kFixedFunctionGouraudVertex << kFixedFunctionGouraudFragment << s << 5
                << kTolerance;
        }
    }

    void drawsAsPasted()
    {
        QFETCH(QString, vertex);
        QFETCH(QString, fragment);
        QFETCH(Scene, scene);
        QFETCH(int, minSpecular);
        QFETCH(int, tolerance);
        const ProgramBuild build = m_offscreen.useProgram(vertex, fragment);
        QVERIFY2(build.ok(), qPrintable(build.log()));
        // Every uniform the program declares is one the scene feeds.
        for (const ActiveUniform &u : build.uniforms)
            QVERIFY2(u.semantic.has_value(), qPrintable(u.name + " is fed nothing"));
        const QString failure = checkAgainstReference(m_offscreen, scene, QTest::currentDataTag(),
                                                      100, minSpecular, tolerance);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
    }

    // Names of no convention, bound by the user (the Bindings view, --bind, the scene file):
    // unbound they draw nothing and the build names each matrix and what it could be; bound
    // they draw as LearnOpenGL's own names do. A convention's name bound to none keeps its own
    // value.
    void userBindingsFeedAnyName()
    {
        const std::pair<const char *, Semantic> renamed[] = {
            {"model", Semantic::Model},
            {"view", Semantic::View},
            {"projection", Semantic::Projection},
            {"lightPos", Semantic::LightPositionWorld},
            {"viewPos", Semantic::CameraPositionWorld},
            {"lightColor", Semantic::LightDiffuse},
            {"objectColor", Semantic::MaterialDiffuse},
        };
        const QStringList ours{"uObjToWorld", "uWorldToView", "uViewToClip", "uLamp",
                               "uEye",        "uLampColour",  "uAlbedo"};
        QString vertex = kLearnOpenGlVertex, fragment = kLearnOpenGlBasicFragment;
        UniformBindings bindings;
        for (std::size_t i = 0; i < std::size(renamed); ++i) {
            const QRegularExpression word(QString("\\b%1\\b").arg(renamed[i].first));
            vertex.replace(word, ours[int(i)]);
            fragment.replace(word, ours[int(i)]);
            bindings[ours[int(i)]] = renamed[i].second;
        }
        const ProgramBuild unbound = m_offscreen.useProgram(vertex, fragment);
        QVERIFY2(unbound.ok(), qPrintable(unbound.log()));
        for (const char *named : {"uObjToWorld", "uWorldToView", "uViewToClip", "uEye=KEY",
                                  "uLamp=KEY", "uLampColour=KEY"})
            QVERIFY2(unbound.log().contains(named), qPrintable(unbound.log()));
        QCOMPARE(unbound.diagnostics.size(), std::size_t(6));
        const Scene scene = basicLightingScene(lightIn(testScene(), LightFrame::World));
        // The frame, collapsed by the zero matrices, is said to show nothing.
        m_offscreen.renderer().lookAtNextFrame();
        m_offscreen.render(scene);
        QCOMPARE(m_offscreen.renderer().takeFrameLook(),
                 std::optional<FrameLook>(FrameLook::AllBackground));

        const ProgramBuild bound = m_offscreen.useProgram(vertex, fragment, {}, bindings);
        QVERIFY2(bound.ok() && bound.diagnostics.empty(), qPrintable(bound.log()));
        for (const ActiveUniform &u : bound.uniforms)
            QVERIFY2(u.semantic && u.bound && !u.byName, qPrintable(u.name));
        m_offscreen.renderer().lookAtNextFrame();
        m_offscreen.render(scene);
        QCOMPARE(m_offscreen.renderer().takeFrameLook(),
                 std::optional<FrameLook>(FrameLook::Drawn));
        const QString failure =
            checkAgainstReference(m_offscreen, scene, "bound by the user", 100, 5, kTolerance);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));

        // A colour that comes out 0 (as one fed nothing does): the object is drawn all black.
        QString black = fragment;
        black.replace("vec3 result = (ambient + diffuse + specular) * uAlbedo;",
                      "vec3 result = (ambient + diffuse + specular) * uAlbedo * 0.0;");
        QVERIFY(black != fragment);
        QVERIFY(m_offscreen.useProgram(vertex, black, {}, bindings).ok());
        m_offscreen.renderer().lookAtNextFrame();
        m_offscreen.render(scene);
        QCOMPARE(m_offscreen.renderer().takeFrameLook(),
                 std::optional<FrameLook>(FrameLook::AllBlack));
        QVERIFY(!frameLookWarning(FrameLook::AllBlack).isEmpty());
        // Looked at once: the next frame is not.
        m_offscreen.render(scene);
        QVERIFY(!m_offscreen.renderer().takeFrameLook());

        const ProgramBuild own = m_offscreen.useProgram(
            kLearnOpenGlVertex, kLearnOpenGlBasicFragment, {}, {{"objectColor", std::nullopt}});
        QVERIFY2(own.ok() && own.diagnostics.empty(), qPrintable(own.log()));
        const auto objectColor =
            std::find_if(own.uniforms.begin(), own.uniforms.end(),
                         [](const ActiveUniform &u) { return u.name == "objectColor"; });
        QVERIFY(objectColor != own.uniforms.end());
        QVERIFY(!objectColor->semantic && objectColor->bound);
        QCOMPARE(objectColor->byName, std::optional<Semantic>(Semantic::MaterialDiffuse));
    }

    // opengl-tutorial.org's names (M, V, MVP, LightPosition_worldspace) are fed; its layout puts
    // the normal at location 2, where the mesh gives texture coordinates: the build says so on
    // the normal's line, and at location 1 (as the warning says) the surface is lit.
    void openGlTutorialNamesAndItsLayout()
    {
        const QString vertex = R"(#version 330 core
layout(location = 0) in vec3 vertexPosition_modelspace;
layout(location = 2) in vec3 vertexNormal_modelspace;
out vec3 normalCamera;
out vec3 toLightCamera;
uniform mat4 MVP;
uniform mat4 V;
uniform mat4 M;
uniform vec3 LightPosition_worldspace;
void main() {
    gl_Position = MVP * vec4(vertexPosition_modelspace, 1.0);
    vec3 p = (V * M * vec4(vertexPosition_modelspace, 1.0)).xyz;
    toLightCamera = (V * vec4(LightPosition_worldspace, 1.0)).xyz - p;
    normalCamera = (V * M * vec4(vertexNormal_modelspace, 0.0)).xyz;
}
)";
        const QString fragment = R"(#version 330 core
in vec3 normalCamera;
in vec3 toLightCamera;
out vec3 color;
void main() {
    color = vec3(0.8, 0.3, 0.2) * clamp(dot(normalize(normalCamera), normalize(toLightCamera)), 0.0, 1.0);
}
)";
        const ProgramBuild misplaced = m_offscreen.useProgram(vertex, fragment);
        QVERIFY2(misplaced.ok(), qPrintable(misplaced.log()));
        for (const ActiveUniform &u : misplaced.uniforms)
            QVERIFY2(u.semantic, qPrintable(u.name + " is fed nothing"));
        QCOMPARE(misplaced.diagnostics.size(), std::size_t(1));
        const Diagnostic &d = misplaced.diagnostics.front();
        QCOMPARE(d.line, 3);
        QVERIFY2(d.message.contains("vertexNormal_modelspace") &&
                     d.message.contains("layout(location = 1)"),
                 qPrintable(d.message));

        QString moved = vertex;
        moved.replace("layout(location = 2)", "layout(location = 1)");
        const ProgramBuild placed = m_offscreen.useProgram(moved, fragment);
        QVERIFY2(placed.ok() && placed.diagnostics.empty(), qPrintable(placed.log()));
        // Lit as the reference's diffuse term with the fragment's colour as Kd: its normals go
        // through V * M itself, so the object is turned, not squashed.
        Scene scene = lightIn(testScene(), LightFrame::World);
        scene.objects[0].scale = glm::vec3(1.0f);
        scene.objects[0].material.kd = glm::vec3(0.8f, 0.3f, 0.2f);
        scene.lights[0].colors.ia = glm::vec3(0.0f);
        scene.lights[0].colors.id = glm::vec3(1.0f); // the program has no light colour
        scene.shading.terms.specular = false;
        const QString failure =
            checkAgainstReference(m_offscreen, scene, "opengl-tutorial", 100, 0, kTolerance);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
    }

    // A GLSL 1.20 program's errors land on the user's lines, with the built-ins' own names;
    // every built-in it uses is fed.
    void fixedFunctionErrorsOnTheirLine()
    {
        QString fragment = kFixedFunctionFragment;
        fragment.replace("float nDotL = max(dot(n, l), 0.0);",
                         "float nDotL = max(dot(n, gl_LightSource[0].position), 0.0);");
        const ProgramBuild broken = m_offscreen.useProgram(kFixedFunctionVertex, fragment);
        QVERIFY(!broken.ok());
        const auto error = std::find_if(
            broken.diagnostics.begin(), broken.diagnostics.end(),
            [](const Diagnostic &d) { return d.severity == Diagnostic::Severity::Error; });
        QVERIFY(error != broken.diagnostics.end());
        QCOMPARE(error->stage, ShaderStage::Fragment);
        QCOMPARE(error->line, 8);
        QVERIFY2(!broken.log().contains("lb_"), qPrintable(broken.log()));

        const ProgramBuild built =
            m_offscreen.useProgram(kFixedFunctionVertex, kFixedFunctionFragment);
        QVERIFY2(built.ok() && built.diagnostics.empty(), qPrintable(built.log()));
        QStringList fed;
        for (const ActiveUniform &u : built.uniforms) {
            QVERIFY2(u.semantic, qPrintable(u.name + " is fed nothing"));
            fed << u.name;
        }
        fed.sort();
        QCOMPARE(fed, QStringList({"lb_FrontLightProduct_ambient", "lb_FrontLightProduct_diffuse",
                                   "lb_FrontLightProduct_specular", "lb_FrontMaterial_shininess",
                                   "lb_LightSource_position", "lb_ModelViewMatrix",
                                   "lb_ModelViewProjectionMatrix", "lb_NormalMatrix"}));
    }

    // What a name in no table says about its slot ("vertex" names the stage, not the input).
    void attributeNamesSayTheirSlot()
    {
        const std::pair<const char *, std::optional<AttributeSlot>> cases[] = {
            {"inVertexPos", kPositionSlot}, {"aVertex", kPositionSlot},
            {"in_Position", kPositionSlot}, {"inVertexNormal", kNormalSlot},
            {"vertex_normal", kNormalSlot}, {"vertexTexCoord", kTexCoordSlot},
            {"myUV", kTexCoordSlot},        {"aColour", kColorSlot},
            {"inVertexColor", kColorSlot},  {"boneWeights", std::nullopt},
        };
        for (const auto &[name, slot] : cases)
            QVERIFY2(slotByNameParts(name) == slot, name);
    }

    // WebGL 1 as browsers run it: a global initialised from uniforms (GLSL ES 1.00 asks for a
    // constant; ANGLE warns and runs it) draws on the default path, with a warning on its line.
    void globalInitialisedFromUniformsRuns()
    {
        const char *vertex =
            "attribute vec4 vPosition;\n"
            "uniform mat4 mModelView;\n"
            "uniform mat4 mProjection;\n"
            "void main() { gl_Position = mProjection * mModelView * vPosition; }\n";
        const char *fragment = "precision mediump float;\n"
                               "uniform vec3 lightDif;\n"
                               "uniform vec3 materialDif;\n"
                               "vec3 diffuseColor = lightDif * materialDif;\n"
                               "void main() { gl_FragColor = vec4(diffuseColor, 1.0); }\n";
        Scene s = testScene();
        s.lights[0].colors.id = glm::vec3(0.8f, 0.6f, 0.4f);
        s.objects[0].material.kd = glm::vec3(1.0f, 0.5f, 0.25f);
        const glm::vec3 expected = s.lights[0].colors.id * s.objects[0].material.kd;
        for (const bool forced : {false, true}) {
            setWebGl1TranslationForced(forced);
            const ProgramBuild build = m_offscreen.useProgram(vertex, fragment);
            setWebGl1TranslationForced(false);
            QVERIFY2(build.ok(), qPrintable(build.log()));
            if (!forced) {
                QVERIFY(!build.diagnostics.empty());
                const Diagnostic &d = build.diagnostics.front();
                QCOMPARE(d.severity, Diagnostic::Severity::Warning);
                QCOMPARE(d.stage, ShaderStage::Fragment);
                QCOMPARE(d.line, 4);
                QVERIFY2(d.message.contains("GLSL 3.30"), qPrintable(d.message));
            }
            const QImage frame = m_offscreen.render(s);
            const QRgb centre = frame.pixel(kSize.width() / 2, kSize.height() / 2);
            QVERIFY2(channelDifference(centre, expected) <= kTolerance,
                     qPrintable(QString("centre %1").arg(centre, 8, 16)));
        }
    }

    // A matrix of a name no convention has: the program draws (the last good one is replaced,
    // as asked), and the build says on its line that nothing feeds it and what would.
    void unfedMatrixIsNamed()
    {
        const ProgramBuild build =
            m_offscreen.useProgram("attribute vec4 aPos;\n"
                                   "uniform mat4 uMyMvp;\n"
                                   "void main() { gl_Position = uMyMvp * aPos; }\n",
                                   "precision mediump float;\n"
                                   "void main() { gl_FragColor = vec4(1.0); }\n");
        QVERIFY2(build.ok(), qPrintable(build.log()));
        QCOMPARE(build.diagnostics.size(), std::size_t(1));
        const Diagnostic &d = build.diagnostics.front();
        QCOMPARE(d.severity, Diagnostic::Severity::Warning);
        QCOMPARE(d.stage, ShaderStage::Vertex);
        QCOMPARE(d.line, 2);
        QVERIFY2(d.message.contains("uMyMvp") &&
                     d.message.contains("one of model-view-projection, "),
                 qPrintable(d.message));
    }

    // A program that reads no position at all is still refused, with the ways it could. (A
    // lone attribute of any name is at location 0, and takes the positions.)
    void noPositionNamesTheWays()
    {
        const ProgramBuild build =
            m_offscreen.useProgram("void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n",
                                   "precision mediump float;\n"
                                   "void main() { gl_FragColor = vec4(1.0); }\n");
        QVERIFY(!build.ok());
        QVERIFY2(build.log().contains("layout(location = 0)") && build.log().contains("aPos"),
                 qPrintable(build.log()));
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestShaderConventions test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_shader_conventions.moc"
