#version 330 core
// A 300-line fragment shader for bench/edit.sh: the built-in Phong shading plus a
// procedural marble pattern made of many small functions, all of which reach the output
// (so the compiler cannot drop them).
// Phong shading, fragment stage: ambient + diffuse + specular for every fragment, in the
// camera frame. L and V are computed here from the interpolated position rather than
// interpolated from the vertices, so a point light close to the surface stays exact.

in vec3 fPosition;
in vec3 fNormal;
in vec3 fColor;
in vec2 fTexCoord;

uniform mat4 mModelView;   // model-view transformation (for a light in object frame)
uniform mat4 mNormals;     // inverse transpose of mModelView
uniform mat4 mView;        // world -> camera, from lookAt()
uniform mat4 mViewNormals; // inverse transpose of mView

uniform vec4 lightPosition; // w = 0: direction towards the light; w = 1: position
uniform int uLightFrame;    // frame lightPosition is given in: 0 camera, 1 world, 2 object
uniform vec3 lightAmb;      // Ia
uniform vec3 lightDif;      // Id
uniform vec3 lightSpe;      // Is
uniform vec3 materialAmb;   // Ka
uniform vec3 materialDif;   // Kd
uniform vec3 materialSpe;   // Ks
uniform float shininess;
uniform int uSpecularModel; // 0: Phong (R.V), 1: Blinn-Phong (N.H)
uniform int uProjection;    // 0: perspective, V = -posC; 1: parallel, V = (0,0,1)

uniform bool uEnableLighting;
uniform bool uEnableVertexColor;
uniform bool uEnableTexture;
uniform sampler2D uSampler;

out vec4 fragColor;

// The light in the camera frame: variants I (camera), II (world) and III (object).
// An inverse transpose carries the matrix's translation into w, so w is put back: a
// direction must stay a direction (w = 0) after mViewNormals or mNormals.
vec4 lightInCamera()
{
    vec4 light = lightPosition;
    if (uLightFrame == 1)
        light = lightPosition.w == 0.0 ? mViewNormals * lightPosition : mView * lightPosition;
    else if (uLightFrame == 2)
        light = lightPosition.w == 0.0 ? mNormals * lightPosition : mModelView * lightPosition;
    return vec4(light.xyz, lightPosition.w);
}

// Hash and value noise, then layers of it.
float hash(vec3 p)
{
    p = fract(p * 0.3183099 + vec3(0.1, 0.2, 0.3));
    p *= 17.0;
    return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

float noise(vec3 x)
{
    vec3 i = floor(x);
    vec3 f = fract(x);
    f = f * f * (3.0 - 2.0 * f);
    return mix(mix(mix(hash(i + vec3(0, 0, 0)), hash(i + vec3(1, 0, 0)), f.x),
                   mix(hash(i + vec3(0, 1, 0)), hash(i + vec3(1, 1, 0)), f.x), f.y),
               mix(mix(hash(i + vec3(0, 0, 1)), hash(i + vec3(1, 0, 1)), f.x),
                   mix(hash(i + vec3(0, 1, 1)), hash(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}

float layer0(vec3 p)
{
    float scale = 1.0 + 0.5 * float(0);
    vec3 q = p * scale + vec3(0.0, 0.0, 0.0);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer1(vec3 p)
{
    float scale = 2.0 + 0.5 * float(1);
    vec3 q = p * scale + vec3(0.7, 1.3, 0.4);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer2(vec3 p)
{
    float scale = 3.0 + 0.5 * float(2);
    vec3 q = p * scale + vec3(1.4, 2.6, 0.8);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer3(vec3 p)
{
    float scale = 4.0 + 0.5 * float(3);
    vec3 q = p * scale + vec3(2.1, 3.9, 1.2);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer4(vec3 p)
{
    float scale = 5.0 + 0.5 * float(4);
    vec3 q = p * scale + vec3(2.8, 5.2, 1.6);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer5(vec3 p)
{
    float scale = 6.0 + 0.5 * float(5);
    vec3 q = p * scale + vec3(3.5, 6.5, 2.0);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer6(vec3 p)
{
    float scale = 7.0 + 0.5 * float(6);
    vec3 q = p * scale + vec3(4.2, 7.8, 2.4);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer7(vec3 p)
{
    float scale = 8.0 + 0.5 * float(7);
    vec3 q = p * scale + vec3(4.9, 9.1, 2.8);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer8(vec3 p)
{
    float scale = 9.0 + 0.5 * float(8);
    vec3 q = p * scale + vec3(5.6, 10.4, 3.2);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer9(vec3 p)
{
    float scale = 10.0 + 0.5 * float(9);
    vec3 q = p * scale + vec3(6.3, 11.7, 3.6);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer10(vec3 p)
{
    float scale = 11.0 + 0.5 * float(10);
    vec3 q = p * scale + vec3(7.0, 13.0, 4.0);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer11(vec3 p)
{
    float scale = 12.0 + 0.5 * float(11);
    vec3 q = p * scale + vec3(7.7, 14.3, 4.4);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer12(vec3 p)
{
    float scale = 13.0 + 0.5 * float(12);
    vec3 q = p * scale + vec3(8.4, 15.6, 4.8);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer13(vec3 p)
{
    float scale = 14.0 + 0.5 * float(13);
    vec3 q = p * scale + vec3(9.1, 16.9, 5.2);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer14(vec3 p)
{
    float scale = 15.0 + 0.5 * float(14);
    vec3 q = p * scale + vec3(9.8, 18.2, 5.6);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer15(vec3 p)
{
    float scale = 16.0 + 0.5 * float(15);
    vec3 q = p * scale + vec3(10.5, 19.5, 6.0);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer16(vec3 p)
{
    float scale = 17.0 + 0.5 * float(16);
    vec3 q = p * scale + vec3(11.2, 20.8, 6.4);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer17(vec3 p)
{
    float scale = 18.0 + 0.5 * float(17);
    vec3 q = p * scale + vec3(11.9, 22.1, 6.8);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer18(vec3 p)
{
    float scale = 19.0 + 0.5 * float(18);
    vec3 q = p * scale + vec3(12.6, 23.4, 7.2);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer19(vec3 p)
{
    float scale = 20.0 + 0.5 * float(19);
    vec3 q = p * scale + vec3(13.3, 24.7, 7.6);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer20(vec3 p)
{
    float scale = 21.0 + 0.5 * float(20);
    vec3 q = p * scale + vec3(14.0, 26.0, 8.0);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer21(vec3 p)
{
    float scale = 22.0 + 0.5 * float(21);
    vec3 q = p * scale + vec3(14.7, 27.3, 8.4);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float layer22(vec3 p)
{
    float scale = 23.0 + 0.5 * float(22);
    vec3 q = p * scale + vec3(15.4, 28.6, 8.8);
    float v = noise(q) * 0.5 + noise(q * 2.0) * 0.25;
    return v / scale;
}

float marble(vec3 p)
{
    float sum = 0.0;
    sum += layer0(p);
    sum += layer1(p);
    sum += layer2(p);
    sum += layer3(p);
    sum += layer4(p);
    sum += layer5(p);
    sum += layer6(p);
    sum += layer7(p);
    sum += layer8(p);
    sum += layer9(p);
    sum += layer10(p);
    sum += layer11(p);
    sum += layer12(p);
    sum += layer13(p);
    sum += layer14(p);
    sum += layer15(p);
    sum += layer16(p);
    sum += layer17(p);
    sum += layer18(p);
    sum += layer19(p);
    sum += layer20(p);
    sum += layer21(p);
    sum += layer22(p);
    return 0.5 + 0.5 * sin(p.x * 4.0 + sum * 6.0);
}

void main()
{
    // Vertex colour and texture modulate the ambient and diffuse reflection.
    vec3 base = vec3(0.75 + 0.25 * marble(fPosition));
    if (uEnableVertexColor)
        base *= fColor;
    if (uEnableTexture)
        base *= texture(uSampler, fTexCoord).rgb;
    if (!uEnableLighting) {
        fragColor = vec4(materialDif * base, 1.0);
        return;
    }

    vec4 light = lightInCamera();
    vec3 L = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - fPosition);
    vec3 V = uProjection == 0 ? normalize(-fPosition) : vec3(0.0, 0.0, 1.0);
    vec3 N = normalize(fNormal);
    vec3 H = normalize(L + V);
    // The slides write reflect(L, N), but GLSL's reflect() mirrors an incident direction that
    // points at the surface; L points away from it, so the mirrored light ray is reflect(-L, N).
    vec3 R = reflect(-L, N);

    vec3 ambient = lightAmb * materialAmb;
    float diffuseFactor = max(dot(L, N), 0.0); // no light from behind
    vec3 diffuse = diffuseFactor * (lightDif * materialDif);
    float specularAngle = uSpecularModel == 1 ? dot(N, H) : dot(R, V);
    vec3 specular = pow(max(specularAngle, 0.0), shininess) * (lightSpe * materialSpe);
    if (dot(L, N) < 0.0)
        specular = vec3(0.0); // light on the back of the face: no highlight

    fragColor = vec4(base * (ambient + diffuse) + specular, 1.0);
}
