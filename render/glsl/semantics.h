#pragma once
// The table of semantic names: which uniform names the workbench feeds from the panels, in
// the slides' spelling (mModelView, lightAmb...), the exercise's (uModelViewMatrix,
// uLightPosition...), the built-in shaders' switches, and those of the tutorials and books a
// student pastes from (LearnOpenGL, webglfundamentals, MDN, Angel and three.js, the GLSL
// Cookbook, glslViewer). Attribute names are in program.cpp.
// The light's names may be arrays (lightPosition[4]): element i is light i + 1; a plain
// uniform is light 1.

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace lb {

enum class Semantic {
    ModelView,         // mat4: mModelView, uModelViewMatrix
    Normals,           // mat4 or mat3: mNormals, uNormalMatrix (inverse transpose of model-view)
    View,              // mat4: mView
    ViewNormals,       // mat4 or mat3: mViewNormals
    Projection,        // mat4: mProjection, uProjectionMatrix
    LightPosition,     // vec4/vec3: lightPosition, as given in the panel's frame (with w)
    LightPositionEye,  // vec3/vec4: uLightPosition, in camera coordinates (the exercise's)
    LightAmbient,      // lightAmb: Ia
    LightDiffuse,      // lightDif, uLightColor: Id
    LightSpecular,     // lightSpe: Is
    MaterialAmbient,   // materialAmb: Ka
    MaterialDiffuse,   // materialDif: Kd
    MaterialSpecular,  // materialSpe: Ks
    Shininess,         // shininess
    LightFrame,        // uLightFrame: 0 camera, 1 world, 2 object
    LightEnabled,      // uLightEnabled: the light's on/off switch
    SpecularModel,     // uSpecularModel: 0 Phong, 1 Blinn-Phong
    ProjectionKind,    // uProjection: 0 perspective, 1 orthographic
    EnableLighting,    // uEnableLighting
    EnableVertexColor, // uEnableVertexColor
    EnableTexture,     // uEnableTexture
    Sampler,           // uSampler: the checker texture on unit 0
    LightAttenuation,  // lightAttenuation: vec3 (kc, kl, kq)
    SpotDirection,     // spotDirection: vec3, the cone's axis in the light's frame
    SpotCutoff,        // spotCutoff: the cone's half-angle in degrees, 180 = no spot
    SpotCosCutoff,     // spotCosCutoff: its cosine, -1 for no spot
    SpotExponent,      // spotExponent
    EnableAmbient,     // uEnableAmbient: the ambient term on or off
    EnableDiffuse,     // uEnableDiffuse
    EnableSpecular,    // uEnableSpecular
    Show,              // uShow: 0 the colour, 1 N, 2 L, 3 V, 4 H, 5 R, 6 N·L, 7 specular, 8 att.
    // What other courses and tutorials feed their own programs (the conventions below).
    Model,                 // mat4: model, u_world: world from object
    ModelNormals,          // mat4 or mat3: u_worldInverseTranspose (inverse transpose of model)
    ViewProjection,        // mat4: u_viewProjection = projection * view
    ModelViewProjection,   // mat4: MVP, u_worldViewProjection
    LightPositionWorld,    // vec3/vec4: lightPos, u_lightWorldPosition, in world coordinates
    LightDirectionWorld,   // vec3: light.direction, where the light shines (world): a spot's
                           // axis, or the way a directional light travels (-L)
    ReverseLightDirection, // vec3: u_reverseLightDirection, towards the light (world), unit
    CameraPositionWorld,   // vec3: viewPos, cameraPosition, the eye in world coordinates
    AmbientProduct,        // vec4: ambientProduct = Ia·Ka (Angel's)
    DiffuseProduct,        // vec4: diffuseProduct = Id·Kd
    SpecularProduct,       // vec4: specularProduct = Is·Ks
    AttenuationConstant,   // float: light.constant, kc of lightAttenuation
    AttenuationLinear,     // float: light.linear, kl
    AttenuationQuadratic,  // float: light.quadratic, kq
    SpotDirectionEye,      // vec3: gl_LightSource[i].spotDirection, the spot's axis (camera)
    HalfVectorEye,         // vec4: gl_LightSource[i].halfVector, normalize(L + (0, 0, 1)) with L
                           // towards the light from the camera (the infinite viewer's H)
};
constexpr Semantic kLastSemantic = Semantic::HalfVectorEye;

// Whose names these are: the course's (the slides', the exercise's, the built-in shaders'
// switches; MDN's WebGL tutorial uses the exercise's) and the tutorials and books students
// copy from.
enum class Convention {
    Course,
    LearnOpenGL,       // learnopengl.com: aPos, model/view/projection, lightPos, material.*
    WebGLFundamentals, // webglfundamentals.org, webgl2fundamentals.org: a_position, u_world
    AngelThreeJs,      // Angel's textbook (MV.js) and three.js: vPosition, modelViewMatrix
    Cookbook,          // the OpenGL 4 Shading Language Cookbook: VertexPosition, Light.Position
    GlslViewer,        // glslViewer: a_position, u_modelViewProjectionMatrix, u_light
    OpenGlTutorial,    // opengl-tutorial.org: MVP, M, V, LightPosition_worldspace
    FixedFunction,     // GLSL 1.20's built-ins, translated (legacy_builtins.h): gl_LightSource
};

// The shape a uniform is declared with, for names that mean different things by type
// (uProjection: an int switch or the projection matrix; material.diffuse: a colour or a
// sampler). Any: the first entry of the name.
enum class UniformShape { Any, Matrix, Number, Sampler };

std::optional<Semantic> semanticOf(const QString &uniformName,
                                   UniformShape shape = UniformShape::Any);
// The course's names fed with `semantic`, the slides' first ("lightDif", "uLightColor"); empty
// for a semantic only the other conventions use.
QStringList uniformNames(Semantic semantic);
// Every name fed with `semantic`, of every convention, the course's first.
QStringList allUniformNames(Semantic semantic);
// The convention a uniform name comes from (the first entry of it); nullopt for none.
std::optional<Convention> conventionOf(const QString &uniformName);
// The course's semantics whose panel controls decide `semantic`'s value: itself for the
// course's own, the inputs for the others (AmbientProduct: LightAmbient and MaterialAmbient;
// LightPositionWorld: LightPosition and LightPositionEye, the position and its frame), so
// that a control a program reads through a tutorial's name is not shown as unused.
std::vector<Semantic> controlledBy(Semantic semantic);
// Whether the value belongs to one light (an array of them holds light i + 1 at element i).
bool isPerLight(Semantic semantic);

} // namespace lb
