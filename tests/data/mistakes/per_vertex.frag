// Per-vertex lighting (see the .vert): the fragment shader only applies it.
precision mediump float;
uniform bool uEnableTexture;
uniform bool uEnableLighting;
uniform sampler2D uSampler;
varying vec3 vColor;
varying vec2 vTextureCoord;
varying vec3 vDiffuse;
varying vec3 vSpecular;
void main ()
{
    vec3 baseColor = uEnableTexture ? texture2D (uSampler, vTextureCoord).rgb : vColor;
    gl_FragColor = vec4 (uEnableLighting ? vDiffuse * baseColor + vSpecular : baseColor, 1.0);
}
