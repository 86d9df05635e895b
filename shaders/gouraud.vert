#version 330 core
// Gouraud shading (slides: "Iluminação nos vértices"): the lighting model is evaluated once
// per vertex, in the camera frame, and the colours are interpolated over each triangle.

in vec4 vPosition;  // vertex position in modelling coordinates
in vec3 vNormal;    // vertex normal in modelling coordinates
in vec3 vColor;     // vertex colour (used when the vertex colour switch is on)
in vec2 vTexCoord;  // texture coordinate (used when the texture switch is on)

uniform mat4 mModelView;   // model-view transformation
uniform mat4 mNormals;     // inverse transpose of mModelView: carries normals
uniform mat4 mView;        // world -> camera, from lookAt()
uniform mat4 mViewNormals; // inverse transpose of mView
uniform mat4 mProjection;  // projection matrix

// Up to four lights; element i is light i + 1 of the Light panel. Their terms add up.
#define MAX_LIGHTS 4
uniform bool uLightEnabled[MAX_LIGHTS];
uniform vec4 lightPosition[MAX_LIGHTS]; // w = 0: direction towards the light; w = 1: position
uniform int uLightFrame[MAX_LIGHTS];    // frame of lightPosition: 0 camera, 1 world, 2 object
uniform vec3 lightAmb[MAX_LIGHTS];      // Ia
uniform vec3 lightDif[MAX_LIGHTS];      // Id
uniform vec3 lightSpe[MAX_LIGHTS];      // Is
// OpenGL 2.1's attenuation and spotlight: (kc, kl, kq) of 1 / (kc + kl d + kq d^2) for a
// point light at distance d; the cone's axis in the light's frame, the cosine of its
// half-angle (-1: no spot) and its exponent. (1, 0, 0) and -1 leave the light as it was.
// The workbench compiles this text with LIGHT_FACTORS 0 while no light that is on has
// either, because evaluating them costs llvmpipe even at these defaults.
#define LIGHT_FACTORS 1
uniform vec3 lightAttenuation[MAX_LIGHTS];
uniform vec3 spotDirection[MAX_LIGHTS];
uniform float spotCosCutoff[MAX_LIGHTS];
uniform float spotExponent[MAX_LIGHTS];
uniform vec3 materialAmb;   // Ka
uniform vec3 materialDif;   // Kd
uniform vec3 materialSpe;   // Ks
uniform float shininess;
uniform int uSpecularModel; // 0: Phong (R.V), 1: Blinn-Phong (N.H)
uniform int uProjection;    // 0: perspective, V = -posC; 1: parallel, V = (0,0,1)
uniform bool uEnableAmbient;  // each term can be switched off to see the others alone
uniform bool uEnableDiffuse;
uniform bool uEnableSpecular;
// What the surface shows: 0 the lit colour; 1 to 5 N, L, V, H, R as 0.5 v + 0.5; 6 N.L,
// 7 the specular factor, 8 the attenuation, as grey. L, H, R and the numbers are light 1's.
// The workbench compiles this text with SHOW_CHOICES 0 while the colour is shown.
#define SHOW_CHOICES 1
uniform int uShow;

// Ambient + diffuse and specular travel apart so that the fragment stage can modulate the
// first by the vertex colour and the texture, as phong.frag does.
// Flat shading is this program with FLAT_SHADING 1 (the workbench compiles it so for the
// Flat choice): each triangle takes the values of its last vertex, GL's provoking vertex,
// uninterpolated.
#define FLAT_SHADING 0
#if FLAT_SHADING
flat out vec3 fAmbientDiffuse;
flat out vec3 fSpecular;
#else
out vec3 fAmbientDiffuse;
out vec3 fSpecular;
#endif
out vec3 fColor;
out vec2 fTexCoord;

// The light in the camera frame: variants I (camera), II (world) and III (object).
// An inverse transpose carries the matrix's translation into w, so w is put back: a
// direction must stay a direction (w = 0) after mViewNormals or mNormals.
vec4 lightInCamera(int i)
{
    vec4 p = lightPosition[i];
    vec4 light = p;
    if (uLightFrame[i] == 1)
        light = p.w == 0.0 ? mViewNormals * p : mView * p;
    else if (uLightFrame[i] == 2)
        light = p.w == 0.0 ? mNormals * p : mModelView * p;
    return vec4(light.xyz, p.w);
}

// The spotlight's axis in the camera frame, carried as a light direction is.
vec3 spotInCamera(int i)
{
    vec4 d = vec4(spotDirection[i], 0.0);
    if (uLightFrame[i] == 1)
        d = mViewNormals * d;
    else if (uLightFrame[i] == 2)
        d = mNormals * d;
    return normalize(d.xyz);
}

// OpenGL 2.1's attenuation of light i at P: 1 / (kc + kl d + kq d^2), 1 for a direction.
float attenuationOf(int i, vec4 light, vec3 P)
{
#if LIGHT_FACTORS == 0
    return 1.0;
#else
    if (light.w == 0.0)
        return 1.0;
    float d = length(light.xyz - P);
    vec3 k = lightAttenuation[i];
    return 1.0 / max(k.x + k.y * d + k.z * d * d, 1e-6);
#endif
}

// Light i's spot factor for the direction L towards it: 0 outside the cone.
float spotOf(int i, vec3 L)
{
#if LIGHT_FACTORS == 0
    return 1.0;
#else
    if (spotCosCutoff[i] <= -1.0)
        return 1.0; // no spot
    float cosAngle = dot(-L, spotInCamera(i));
    if (cosAngle < spotCosCutoff[i])
        return 0.0;
    if (spotExponent[i] == 0.0) // pow(0, 0) is undefined in GLSL; here it is 1
        return 1.0;
    return pow(max(cosAngle, 0.0), spotExponent[i]);
#endif
}

// What uShow asks for at P, from light 1.
vec3 shown(vec3 P, vec3 N, vec3 V)
{
    vec4 light = lightInCamera(0);
    vec3 L = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - P);
    vec3 H = normalize(L + V);
    vec3 R = reflect(-L, N);
    if (uShow <= 5) {
        vec3 v = uShow == 1 ? N : uShow == 2 ? L : uShow == 3 ? V : uShow == 4 ? H : R;
        return 0.5 * v + 0.5;
    }
    if (uShow == 6)
        return vec3(dot(L, N)); // negative (the light behind) shows black
    if (uShow == 7) {
        float specularAngle = uSpecularModel == 1 ? dot(N, H) : dot(R, V);
        return vec3(dot(L, N) < 0.0 ? 0.0 : pow(max(specularAngle, 0.0), shininess));
    }
    return vec3(attenuationOf(0, light, P));
}

// One light's terms at P (camera frame), added to the sums.
void addLight(int i, vec3 P, vec3 N, vec3 V, inout vec3 ambientDiffuse, inout vec3 specular)
{
    vec4 light = lightInCamera(i);
    vec3 L = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - P);
    float factor = attenuationOf(i, light, P) * spotOf(i, L); // scales all three terms
    vec3 H = normalize(L + V);
    // The slides write reflect(L, N), but GLSL's reflect() mirrors an incident direction that
    // points at the surface; L points away from it, so the mirrored light ray is reflect(-L, N).
    vec3 R = reflect(-L, N);

    vec3 ambient = lightAmb[i] * materialAmb;
    float diffuseFactor = max(dot(L, N), 0.0); // no light from behind
    vec3 diffuse = diffuseFactor * (lightDif[i] * materialDif);
    float specularAngle = uSpecularModel == 1 ? dot(N, H) : dot(R, V);
    vec3 spec = pow(max(specularAngle, 0.0), shininess) * (lightSpe[i] * materialSpe);
    if (dot(L, N) < 0.0)
        spec = vec3(0.0); // light on the back of the face: no highlight

    if (uEnableAmbient)
        ambientDiffuse += factor * ambient;
    if (uEnableDiffuse)
        ambientDiffuse += factor * diffuse;
    if (uEnableSpecular)
        specular += factor * spec;
}

void main()
{
    vec3 posC = (mModelView * vPosition).xyz;

    vec3 V = uProjection == 0 ? normalize(-posC) : vec3(0.0, 0.0, 1.0);
    vec3 N = normalize((mNormals * vec4(vNormal, 0.0)).xyz);
    vec3 ambientDiffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i)
        if (uLightEnabled[i])
            addLight(i, posC, N, V, ambientDiffuse, specular);
#if SHOW_CHOICES
    if (uShow != 0) { // what is shown instead, interpolated as the colour would be
        ambientDiffuse = shown(posC, N, V);
        specular = vec3(0.0);
    }
#endif

    fAmbientDiffuse = ambientDiffuse;
    fSpecular = specular;
    fColor = vColor;
    fTexCoord = vTexCoord;
    gl_Position = mProjection * mModelView * vPosition;
}
