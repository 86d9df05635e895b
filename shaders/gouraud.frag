#version 330 core
// Gouraud shading, fragment stage: the interpolated vertex colour is the pixel's colour
// (modulated by the vertex colour and the texture when those are on).

// 1: flat shading, one colour per triangle (see gouraud.vert).
#define FLAT_SHADING 0
#if FLAT_SHADING
flat in vec3 fAmbientDiffuse;
flat in vec3 fSpecular;
#else
in vec3 fAmbientDiffuse;
in vec3 fSpecular;
#endif
in vec3 fColor;
in vec2 fTexCoord;

uniform vec3 materialDif; // Kd, shown as is when lighting is off
uniform bool uEnableLighting;
uniform bool uEnableVertexColor;
uniform bool uEnableTexture;
uniform sampler2D uSampler;
// Not 0: fAmbientDiffuse holds a vector or number of the model, shown as is (gouraud.vert).
#define SHOW_CHOICES 1
uniform int uShow;

out vec4 fragColor;

void main()
{
#if SHOW_CHOICES
    if (uShow != 0) {
        fragColor = vec4(fAmbientDiffuse, 1.0);
        return;
    }
#endif
    vec3 base = vec3(1.0);
    if (uEnableVertexColor)
        base *= fColor;
    if (uEnableTexture)
        base *= texture(uSampler, fTexCoord).rgb;
    if (!uEnableLighting) {
        fragColor = vec4(materialDif * base, 1.0);
        return;
    }
    fragColor = vec4(base * fAmbientDiffuse + fSpecular, 1.0);
}
