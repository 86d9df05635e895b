#version 330 core
// Toon shading, the exercise's Aufgabe 4 ("like Zelda"). The vertex stage carries position,
// normal and light vector in the camera frame; the light is given in world coordinates (the
// slides' variant II) by the Light panel.
in vec4 vPosition;
in vec4 vNormal;

uniform mat4 mModelView;
uniform mat4 mNormals;
uniform mat4 mView;
uniform mat4 mViewNormals;
uniform mat4 mProjection;
uniform vec4 lightPosition;

out vec3 fPosition;
out vec3 fNormal;
out vec3 fLight;

void main()
{
    vec3 posC = (mModelView * vPosition).xyz;
    fPosition = posC;
    fNormal = (mNormals * vNormal).xyz;
    if (lightPosition.w == 0.0)
        fLight = (mViewNormals * lightPosition).xyz;
    else
        fLight = (mView * lightPosition).xyz - posC;
    gl_Position = mProjection * vec4(posC, 1.0);
}
