// The lighting model: the same text in the Phong program's fragment stage and the Gouraud
// program's vertex stage (the workbench keeps it once, in shaders/lighting.glsl, and puts it
// in both). Everything is in the camera frame, as in the slides.

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
// The specular models, numbered as the workbench's table of models numbers them
// (render/model/lighting/lighting_models.cpp: each model's uniform value).
#define SPECULAR_PHONG 0 // (R.V)^n
#define SPECULAR_BLINN 1 // (N.H)^n, Blinn-Phong
uniform int uSpecularModel;
uniform int uProjection;    // 0: perspective, V = -posC; 1: parallel, V = (0,0,1)
uniform bool uEnableAmbient;  // each term can be switched off to see the others alone
uniform bool uEnableDiffuse;
uniform bool uEnableSpecular;
// What the surface shows: 0 the lit colour; 1 to 5 N, L, V, H, R as 0.5 v + 0.5; 6 N.L,
// 7 the specular factor, 8 the attenuation, as grey. L, H, R and the numbers are light 1's.
// The workbench compiles this text with SHOW_CHOICES 0 while the colour is shown.
#define SHOW_CHOICES 1
uniform int uShow;

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

// The cosine the specular exponent raises, in the model uSpecularModel names. The slides
// write reflect(L, N), but GLSL's reflect() mirrors an incident direction that points at the
// surface; L points away from it, so the mirrored light ray is reflect(-L, N).
float specularCosine(vec3 N, vec3 L, vec3 V)
{
    if (uSpecularModel == SPECULAR_PHONG)
        return dot(reflect(-L, N), V); // R.V
    if (uSpecularModel == SPECULAR_BLINN)
        return dot(N, normalize(L + V)); // N.H, H the half vector
    return -1.0; // a model this text does not know: no highlight (never another model's)
}

// max(cosine, 0)^shininess, and none where the light is on the back of the face.
float specularFactor(vec3 N, vec3 L, vec3 V)
{
    if (dot(L, N) < 0.0)
        return 0.0;
    return pow(max(specularCosine(N, L, V), 0.0), shininess);
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
    if (uShow == 7)
        return vec3(specularFactor(N, L, V));
    return vec3(attenuationOf(0, light, P));
}

// One light's terms at P (camera frame), added to the sums.
void addLight(int i, vec3 P, vec3 N, vec3 V, inout vec3 ambientDiffuse, inout vec3 specular)
{
    vec4 light = lightInCamera(i);
    vec3 L = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - P);
    float factor = attenuationOf(i, light, P) * spotOf(i, L); // scales all three terms

    vec3 ambient = lightAmb[i] * materialAmb;
    float diffuseFactor = max(dot(L, N), 0.0); // no light from behind
    vec3 diffuse = diffuseFactor * (lightDif[i] * materialDif);
    vec3 spec = specularFactor(N, L, V) * (lightSpe[i] * materialSpe);

    if (uEnableAmbient)
        ambientDiffuse += factor * ambient;
    if (uEnableDiffuse)
        ambientDiffuse += factor * diffuse;
    if (uEnableSpecular)
        specular += factor * spec;
}
