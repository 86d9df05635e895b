#version 330 core
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

void main()
{
    // Vertex colour and texture modulate the ambient and diffuse reflection.
    vec3 base = vec3(1.0);
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
