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

// Ambient + diffuse and specular travel apart so that the fragment stage can modulate the
// first by the vertex colour and the texture, as phong.frag does.
out vec3 fAmbientDiffuse;
out vec3 fSpecular;
out vec3 fColor;
out vec2 fTexCoord;

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
    vec3 posC = (mModelView * vPosition).xyz;

    vec4 light = lightInCamera();
    vec3 L = light.w == 0.0 ? normalize(light.xyz) : normalize(light.xyz - posC);
    vec3 V = uProjection == 0 ? normalize(-posC) : vec3(0.0, 0.0, 1.0);
    vec3 N = normalize((mNormals * vec4(vNormal, 0.0)).xyz);
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

    fAmbientDiffuse = ambient + diffuse;
    fSpecular = specular;
    fColor = vColor;
    fTexCoord = vTexCoord;
    gl_Position = mProjection * mModelView * vPosition;
}
