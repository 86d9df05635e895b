#version 330 core
// "Show normals": one short line per vertex, drawn as an instance of two vertices (gl_VertexID
// 0 at the surface, 1 at the tip). The normal is brought to eye space by the normal matrix,
// so the lines show what the lighting model uses, also under a non-uniform scale.
in vec4 vPosition;
in vec4 vNormal;
uniform mat4 mModelView;
uniform mat4 mNormals;
uniform mat4 mProjection;
uniform float uLineLength; // in eye-space units

void main()
{
    vec4 p = mModelView * vPosition;
    vec3 n = normalize((mNormals * vNormal).xyz);
    gl_Position = mProjection * vec4(p.xyz + float(gl_VertexID) * uLineLength * n, 1.0);
}
