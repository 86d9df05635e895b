#version 330 core
// The vertex stage of bench/shaders/long.frag: the built-in Phong vertex shader.
// Phong shading (slides: "Iluminação nos fragmentos"), vertex stage.
// It only carries the position and normal in the camera frame (plus colour and texture
// coordinate) to the fragments; the lighting model is evaluated per fragment in phong.frag.

in vec4 vPosition;  // vertex position in modelling coordinates
in vec3 vNormal;    // vertex normal in modelling coordinates
in vec3 vColor;     // vertex colour (used when the vertex colour switch is on)
in vec2 vTexCoord;  // texture coordinate (used when the texture switch is on)

uniform mat4 mModelView;   // model-view transformation
uniform mat4 mNormals;     // inverse transpose of mModelView: carries normals
uniform mat4 mProjection;  // projection matrix

out vec3 fPosition;  // posC: position in the camera frame
out vec3 fNormal;    // normal in the camera frame (renormalised per fragment)
out vec3 fColor;
out vec2 fTexCoord;

void main()
{
    vec4 posC = mModelView * vPosition;
    fPosition = posC.xyz;
    fNormal = (mNormals * vec4(vNormal, 0.0)).xyz;
    fColor = vColor;
    fTexCoord = vTexCoord;
    gl_Position = mProjection * posC;
}
