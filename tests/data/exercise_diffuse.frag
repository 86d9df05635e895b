// A student's answer to the exercise's Aufgabe 2, diffuse term only: the light position
// comes in camera coordinates (uLightPosition) and its colour as uLightColor.
precision mediump float;
uniform vec3 uLightPosition;
uniform vec3 uLightColor;
varying vec3 vColor;
varying vec2 vTextureCoord;
varying vec3 vNormalEye;
varying vec3 vVertexPositionEye3;
void main ()
{
    vec3 lightDirectionEye = normalize (uLightPosition - vVertexPositionEye3);
    vec3 normal = normalize (vNormalEye);
    float diffuseFactor = max (dot (normal, lightDirectionEye), 0.0);
    gl_FragColor = vec4 (diffuseFactor * uLightColor, 1.0);
}
