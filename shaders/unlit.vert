#version 330 core
// The light's marker: drawn in one flat colour, untouched by the lighting model.
in vec4 vPosition;
uniform mat4 mModelView;
uniform mat4 mProjection;

void main() { gl_Position = mProjection * mModelView * vPosition; }
