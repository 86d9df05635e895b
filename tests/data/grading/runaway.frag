// A loop whose condition never fails (t tends to 1.0 and stays there), which the loop
// reader cannot bound: llvmpipe stops it after 65,535 steps, seconds a frame. Refused by
// its cost, in well under a second.
precision mediump float;
uniform bool uEnableTexture;
uniform bool uEnableLighting;
uniform vec3 uLightPosition;
uniform vec3 uLightColor;
varying vec3 vColor;
varying vec2 vTextureCoord;
varying vec3 vNormalEye;
varying vec3 vVertexPositionEye3;
uniform sampler2D uSampler;
const float ambientFactor = 0.2;
const float shininess = 10.0;
const vec3 specularMaterialColor = vec3 (0.4, 0.4, 0.4);
void main ()
{
    vec3 baseColor = uEnableTexture ? texture2D (uSampler, vTextureCoord).rgb : vColor;
    if (!uEnableLighting) {
        gl_FragColor = vec4 (baseColor, 1.0);
        return;
    }
    vec3 n = normalize (vNormalEye);
    float t = 1.0;
    while (t > 0.0)
        t = t * 0.5 + 0.5;
    n *= t;
    vec3 l = normalize (uLightPosition - vVertexPositionEye3);
    float diffuseFactor = max (dot (n, l), 0.0);
    vec3 color = ambientFactor * baseColor + diffuseFactor * uLightColor * baseColor;
    if (diffuseFactor > 0.0) {
        vec3 r = reflect (-l, n);
        vec3 v = normalize (-vVertexPositionEye3);
        color += pow (max (dot (r, v), 0.0), shininess) * uLightColor * specularMaterialColor;
    }
    gl_FragColor = vec4 (color, 1.0);
}
