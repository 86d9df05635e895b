#include "semantics.h"

namespace lb {

namespace {

using S = Semantic;
using Sh = UniformShape;
using C = Convention;

struct Entry
{
    const char *name;
    Semantic semantic;
    UniformShape shape;
    Convention convention;
};

// One row a name; a name may come twice with different shapes (uProjection). The course's
// names first: they are the ones the panels' tooltips name.
const Entry kTable[] = {
    {"mModelView", S::ModelView, Sh::Matrix, C::Course},
    {"uModelViewMatrix", S::ModelView, Sh::Matrix, C::Course},
    {"mNormals", S::Normals, Sh::Matrix, C::Course},
    {"uNormalMatrix", S::Normals, Sh::Matrix, C::Course},
    {"mView", S::View, Sh::Matrix, C::Course},
    {"mViewNormals", S::ViewNormals, Sh::Matrix, C::Course},
    {"mProjection", S::Projection, Sh::Matrix, C::Course},
    {"uProjectionMatrix", S::Projection, Sh::Matrix, C::Course},
    {"lightPosition", S::LightPosition, Sh::Number, C::Course},
    {"uLightPosition", S::LightPositionEye, Sh::Number, C::Course},
    {"lightAmb", S::LightAmbient, Sh::Number, C::Course},
    {"lightDif", S::LightDiffuse, Sh::Number, C::Course},
    {"uLightColor", S::LightDiffuse, Sh::Number, C::Course},
    {"lightSpe", S::LightSpecular, Sh::Number, C::Course},
    {"materialAmb", S::MaterialAmbient, Sh::Number, C::Course},
    {"materialDif", S::MaterialDiffuse, Sh::Number, C::Course},
    {"materialSpe", S::MaterialSpecular, Sh::Number, C::Course},
    {"shininess", S::Shininess, Sh::Number, C::Course},
    {"uLightFrame", S::LightFrame, Sh::Number, C::Course},
    {"uLightEnabled", S::LightEnabled, Sh::Number, C::Course},
    {"uSpecularModel", S::SpecularModel, Sh::Number, C::Course},
    {"uProjection", S::ProjectionKind, Sh::Number, C::Course},
    {"uEnableLighting", S::EnableLighting, Sh::Number, C::Course},
    {"uEnableVertexColor", S::EnableVertexColor, Sh::Number, C::Course},
    {"uEnableTexture", S::EnableTexture, Sh::Number, C::Course},
    {"uSampler", S::Sampler, Sh::Sampler, C::Course},
    {"lightAttenuation", S::LightAttenuation, Sh::Number, C::Course},
    {"spotDirection", S::SpotDirection, Sh::Number, C::Course},
    {"spotCutoff", S::SpotCutoff, Sh::Number, C::Course},
    {"spotCosCutoff", S::SpotCosCutoff, Sh::Number, C::Course},
    {"spotExponent", S::SpotExponent, Sh::Number, C::Course},
    {"uEnableAmbient", S::EnableAmbient, Sh::Number, C::Course},
    {"uEnableDiffuse", S::EnableDiffuse, Sh::Number, C::Course},
    {"uEnableSpecular", S::EnableSpecular, Sh::Number, C::Course},
    {"uShow", S::Show, Sh::Number, C::Course},

    // LearnOpenGL's lighting chapters: lighting in world space, the light's and material's
    // colours as structs (light casters: direction, attenuation, cutOff as a cosine).
    {"model", S::Model, Sh::Matrix, C::LearnOpenGL},
    {"view", S::View, Sh::Matrix, C::LearnOpenGL},
    {"projection", S::Projection, Sh::Matrix, C::LearnOpenGL},
    {"lightPos", S::LightPositionWorld, Sh::Number, C::LearnOpenGL},
    {"viewPos", S::CameraPositionWorld, Sh::Number, C::LearnOpenGL},
    {"lightColor", S::LightDiffuse, Sh::Number, C::LearnOpenGL},
    {"objectColor", S::MaterialDiffuse, Sh::Number, C::LearnOpenGL},
    {"material.ambient", S::MaterialAmbient, Sh::Number, C::LearnOpenGL},
    {"material.diffuse", S::MaterialDiffuse, Sh::Number, C::LearnOpenGL},
    {"material.diffuse", S::Sampler, Sh::Sampler, C::LearnOpenGL}, // the lighting maps' one
    {"material.specular", S::MaterialSpecular, Sh::Number, C::LearnOpenGL},
    {"material.specular", S::Sampler, Sh::Sampler, C::LearnOpenGL}, // the texture stands in
    {"material.shininess", S::Shininess, Sh::Number, C::LearnOpenGL},
    {"light.position", S::LightPositionWorld, Sh::Number, C::LearnOpenGL},
    {"light.direction", S::LightDirectionWorld, Sh::Number, C::LearnOpenGL},
    {"light.ambient", S::LightAmbient, Sh::Number, C::LearnOpenGL},
    {"light.diffuse", S::LightDiffuse, Sh::Number, C::LearnOpenGL},
    {"light.specular", S::LightSpecular, Sh::Number, C::LearnOpenGL},
    {"light.constant", S::AttenuationConstant, Sh::Number, C::LearnOpenGL},
    {"light.linear", S::AttenuationLinear, Sh::Number, C::LearnOpenGL},
    {"light.quadratic", S::AttenuationQuadratic, Sh::Number, C::LearnOpenGL},
    {"light.cutOff", S::SpotCosCutoff, Sh::Number, C::LearnOpenGL},
    {"texture_diffuse1", S::Sampler, Sh::Sampler, C::LearnOpenGL},
    {"texture1", S::Sampler, Sh::Sampler, C::LearnOpenGL},

    // webglfundamentals and webgl2fundamentals: world space, a directional light's reverse
    // direction, a spot's direction and limit (a cosine).
    {"u_world", S::Model, Sh::Matrix, C::WebGLFundamentals},
    {"u_worldInverseTranspose", S::ModelNormals, Sh::Matrix, C::WebGLFundamentals},
    {"u_worldViewProjection", S::ModelViewProjection, Sh::Matrix, C::WebGLFundamentals},
    {"u_matrix", S::ModelViewProjection, Sh::Matrix, C::WebGLFundamentals},
    {"u_view", S::View, Sh::Matrix, C::WebGLFundamentals},
    {"u_projection", S::Projection, Sh::Matrix, C::WebGLFundamentals},
    {"u_viewProjection", S::ViewProjection, Sh::Matrix, C::WebGLFundamentals},
    {"u_lightWorldPosition", S::LightPositionWorld, Sh::Number, C::WebGLFundamentals},
    {"u_viewWorldPosition", S::CameraPositionWorld, Sh::Number, C::WebGLFundamentals},
    {"u_reverseLightDirection", S::ReverseLightDirection, Sh::Number, C::WebGLFundamentals},
    {"u_lightDirection", S::LightDirectionWorld, Sh::Number, C::WebGLFundamentals},
    {"u_limit", S::SpotCosCutoff, Sh::Number, C::WebGLFundamentals},
    {"u_color", S::MaterialDiffuse, Sh::Number, C::WebGLFundamentals},
    {"u_shininess", S::Shininess, Sh::Number, C::WebGLFundamentals},
    {"u_lightColor", S::LightDiffuse, Sh::Number, C::WebGLFundamentals},
    {"u_specularColor", S::LightSpecular, Sh::Number, C::WebGLFundamentals},
    {"u_texture", S::Sampler, Sh::Sampler, C::WebGLFundamentals},

    // MDN's WebGL tutorial: its names are the exercise's (uModelViewMatrix, uNormalMatrix,
    // uSampler), above.

    // Angel's textbook (MV.js) and three.js's ShaderMaterial: eye space, the products of the
    // light's and the material's colours.
    {"modelViewMatrix", S::ModelView, Sh::Matrix, C::AngelThreeJs},
    {"projectionMatrix", S::Projection, Sh::Matrix, C::AngelThreeJs},
    {"normalMatrix", S::Normals, Sh::Matrix, C::AngelThreeJs},
    {"modelMatrix", S::Model, Sh::Matrix, C::AngelThreeJs},
    {"viewMatrix", S::View, Sh::Matrix, C::AngelThreeJs},
    {"cameraPosition", S::CameraPositionWorld, Sh::Number, C::AngelThreeJs},
    {"ambientProduct", S::AmbientProduct, Sh::Number, C::AngelThreeJs},
    {"diffuseProduct", S::DiffuseProduct, Sh::Number, C::AngelThreeJs},
    {"specularProduct", S::SpecularProduct, Sh::Number, C::AngelThreeJs},
    {"diffuse", S::MaterialDiffuse, Sh::Number, C::AngelThreeJs}, // three.js's materials
    {"specular", S::MaterialSpecular, Sh::Number, C::AngelThreeJs},
    {"ambientLightColor", S::LightAmbient, Sh::Number, C::AngelThreeJs},

    // The OpenGL 4 Shading Language Cookbook: eye space, its LightInfo and MaterialInfo
    // structs (La, Ld, Ls; the third edition's L for the diffuse and specular light).
    {"ModelViewMatrix", S::ModelView, Sh::Matrix, C::Cookbook},
    {"NormalMatrix", S::Normals, Sh::Matrix, C::Cookbook},
    {"ProjectionMatrix", S::Projection, Sh::Matrix, C::Cookbook},
    {"MVP", S::ModelViewProjection, Sh::Matrix, C::Cookbook},
    {"Light.Position", S::LightPositionEye, Sh::Number, C::Cookbook},
    {"Light.La", S::LightAmbient, Sh::Number, C::Cookbook},
    {"Light.Ld", S::LightDiffuse, Sh::Number, C::Cookbook},
    {"Light.L", S::LightDiffuse, Sh::Number, C::Cookbook},
    {"Light.Ls", S::LightSpecular, Sh::Number, C::Cookbook},
    {"Material.Ka", S::MaterialAmbient, Sh::Number, C::Cookbook},
    {"Material.Kd", S::MaterialDiffuse, Sh::Number, C::Cookbook},
    {"Material.Ks", S::MaterialSpecular, Sh::Number, C::Cookbook},
    {"Material.Shininess", S::Shininess, Sh::Number, C::Cookbook},

    // glslViewer: world space, the light and the camera as positions.
    {"u_modelViewProjectionMatrix", S::ModelViewProjection, Sh::Matrix, C::GlslViewer},
    {"u_modelMatrix", S::Model, Sh::Matrix, C::GlslViewer},
    {"u_viewMatrix", S::View, Sh::Matrix, C::GlslViewer},
    {"u_projectionMatrix", S::Projection, Sh::Matrix, C::GlslViewer},
    {"u_light", S::LightPositionWorld, Sh::Number, C::GlslViewer},
    {"u_camera", S::CameraPositionWorld, Sh::Number, C::GlslViewer},

    // opengl-tutorial.org (its MVP is the Cookbook's, above): the matrices by one letter, the
    // light in world space; its layout puts the texture coordinates at 1 and the normal at 2,
    // the other way round from LearnOpenGL's (the build says so: misplacedInputWarnings).
    {"M", S::Model, Sh::Matrix, C::OpenGlTutorial},
    {"V", S::View, Sh::Matrix, C::OpenGlTutorial},
    {"P", S::Projection, Sh::Matrix, C::OpenGlTutorial},
    {"LightPosition_worldspace", S::LightPositionWorld, Sh::Number, C::OpenGlTutorial},
    {"myTextureSampler", S::Sampler, Sh::Sampler, C::OpenGlTutorial},

    // GLSL 1.10 to 1.30's built-ins as the legacy translation names them (legacy_builtins.h):
    // eye space, as the fixed-function pipeline computes; one light per array element.
    {"lb_ModelViewMatrix", S::ModelView, Sh::Matrix, C::FixedFunction},
    {"lb_ProjectionMatrix", S::Projection, Sh::Matrix, C::FixedFunction},
    {"lb_ModelViewProjectionMatrix", S::ModelViewProjection, Sh::Matrix, C::FixedFunction},
    {"lb_NormalMatrix", S::Normals, Sh::Matrix, C::FixedFunction},
    {"lb_LightSource_position", S::LightPositionEye, Sh::Number, C::FixedFunction},
    {"lb_LightSource_ambient", S::LightAmbient, Sh::Number, C::FixedFunction},
    {"lb_LightSource_diffuse", S::LightDiffuse, Sh::Number, C::FixedFunction},
    {"lb_LightSource_specular", S::LightSpecular, Sh::Number, C::FixedFunction},
    {"lb_LightSource_halfVector", S::HalfVectorEye, Sh::Number, C::FixedFunction},
    {"lb_LightSource_spotDirection", S::SpotDirectionEye, Sh::Number, C::FixedFunction},
    {"lb_LightSource_spotExponent", S::SpotExponent, Sh::Number, C::FixedFunction},
    {"lb_LightSource_spotCutoff", S::SpotCutoff, Sh::Number, C::FixedFunction},
    {"lb_LightSource_spotCosCutoff", S::SpotCosCutoff, Sh::Number, C::FixedFunction},
    {"lb_LightSource_constantAttenuation", S::AttenuationConstant, Sh::Number, C::FixedFunction},
    {"lb_LightSource_linearAttenuation", S::AttenuationLinear, Sh::Number, C::FixedFunction},
    {"lb_LightSource_quadraticAttenuation", S::AttenuationQuadratic, Sh::Number, C::FixedFunction},
    {"lb_FrontLightProduct_ambient", S::AmbientProduct, Sh::Number, C::FixedFunction},
    {"lb_FrontLightProduct_diffuse", S::DiffuseProduct, Sh::Number, C::FixedFunction},
    {"lb_FrontLightProduct_specular", S::SpecularProduct, Sh::Number, C::FixedFunction},
    {"lb_FrontMaterial_ambient", S::MaterialAmbient, Sh::Number, C::FixedFunction},
    {"lb_FrontMaterial_diffuse", S::MaterialDiffuse, Sh::Number, C::FixedFunction},
    {"lb_FrontMaterial_specular", S::MaterialSpecular, Sh::Number, C::FixedFunction},
    {"lb_FrontMaterial_shininess", S::Shininess, Sh::Number, C::FixedFunction},

    // The course's uProjection above is the int switch; declared as a mat4 (a name many
    // students give the projection matrix) it is the matrix.
    {"uProjection", S::Projection, Sh::Matrix, C::Course},
};

} // namespace

std::optional<Semantic> semanticOf(const QString &uniformName, UniformShape shape)
{
    for (const Entry &e : kTable)
        if ((shape == Sh::Any || e.shape == shape) && uniformName == QLatin1String(e.name))
            return e.semantic;
    return std::nullopt;
}

QStringList uniformNames(Semantic semantic)
{
    QStringList names;
    for (const Entry &e : kTable)
        if (e.semantic == semantic && e.convention == C::Course &&
            !names.contains(QLatin1String(e.name)))
            names << QString::fromLatin1(e.name);
    return names;
}

QStringList allUniformNames(Semantic semantic)
{
    QStringList names;
    for (const Entry &e : kTable)
        if (e.semantic == semantic && !names.contains(QLatin1String(e.name)))
            names << QString::fromLatin1(e.name);
    return names;
}

std::optional<Convention> conventionOf(const QString &uniformName)
{
    for (const Entry &e : kTable)
        if (uniformName == QLatin1String(e.name))
            return e.convention;
    return std::nullopt;
}

std::vector<Semantic> controlledBy(Semantic semantic)
{
    switch (semantic) {
    case S::ViewProjection:
    case S::ModelViewProjection:
        return {S::Projection};
    case S::LightPositionWorld:
    case S::ReverseLightDirection:
        return {S::LightPosition, S::LightPositionEye};
    case S::LightDirectionWorld:
        return {S::LightPosition, S::LightPositionEye, S::SpotDirection};
    case S::SpotDirectionEye:
        return {S::SpotDirection};
    case S::HalfVectorEye:
        return {S::LightPosition, S::LightPositionEye};
    case S::AmbientProduct:
        return {S::LightAmbient, S::MaterialAmbient};
    case S::DiffuseProduct:
        return {S::LightDiffuse, S::MaterialDiffuse};
    case S::SpecularProduct:
        return {S::LightSpecular, S::MaterialSpecular};
    case S::AttenuationConstant:
    case S::AttenuationLinear:
    case S::AttenuationQuadratic:
        return {S::LightAttenuation};
    case S::Model:        // the Object panel's, which shows no usage
    case S::ModelNormals: // likewise
    case S::CameraPositionWorld:
        return {};
    default:
        return {semantic};
    }
}

bool isPerLight(Semantic semantic)
{
    switch (semantic) {
    case Semantic::LightPosition:
    case Semantic::LightPositionEye:
    case Semantic::LightAmbient:
    case Semantic::LightDiffuse:
    case Semantic::LightSpecular:
    case Semantic::LightFrame:
    case Semantic::LightEnabled:
    case Semantic::LightAttenuation:
    case Semantic::SpotDirection:
    case Semantic::SpotCutoff:
    case Semantic::SpotCosCutoff:
    case Semantic::SpotExponent:
    case Semantic::LightPositionWorld:
    case Semantic::LightDirectionWorld:
    case Semantic::ReverseLightDirection:
    case Semantic::AmbientProduct:
    case Semantic::DiffuseProduct:
    case Semantic::SpecularProduct:
    case Semantic::AttenuationConstant:
    case Semantic::AttenuationLinear:
    case Semantic::AttenuationQuadratic:
    case Semantic::SpotDirectionEye:
    case Semantic::HalfVectorEye:
        return true;
    default:
        return false;
    }
}

} // namespace lb
