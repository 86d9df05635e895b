#version 330 core
// The difference view: one triangle that covers the viewport.
in vec4 vPosition; // (-1,-1), (3,-1), (-1,3)
out vec2 fUV;

void main()
{
    fUV = vPosition.xy * 0.5 + 0.5;
    gl_Position = vec4(vPosition.xy, 0.0, 1.0);
}
