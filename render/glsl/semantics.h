#pragma once
// The table of semantic names: which uniform names the workbench feeds from the panels, in
// the slides' spelling (mModelView, lightAmb...), the exercise's (uModelViewMatrix,
// uLightPosition...) and the built-in shaders' switches. Attribute names are in program.cpp.
// The light's names may be arrays (lightPosition[4]): element i is light i + 1; a plain
// uniform is light 1.

#include <QString>
#include <QStringList>

#include <optional>

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
};

std::optional<Semantic> semanticOf(const QString &uniformName);
// Every name fed with `semantic`, the slides' first ("lightDif", "uLightColor").
QStringList uniformNames(Semantic semantic);
// Whether the value belongs to one light (an array of them holds light i + 1 at element i).
bool isPerLight(Semantic semantic);

} // namespace lb
