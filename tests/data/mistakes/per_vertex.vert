// The light computed in the vertex shader (Gouraud) although the sheet asks for it per
// fragment (a listed mistake: "per vertex"); the texture is still read per fragment.
attribute vec3 aVertexPosition;
attribute vec3 aVertexColor;
attribute vec3 aVertexNormal;
attribute vec2 aVertexTextureCoord;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
uniform mat3 uNormalMatrix;
uniform vec3 uLightPosition;
uniform vec3 uLightColor;
varying vec3 vColor;
varying vec2 vTextureCoord;
varying vec3 vDiffuse;  // ambient and diffuse weight of the base colour
varying vec3 vSpecular; // added on top
void main ()
{
    vec4 p = uModelViewMatrix * vec4 (aVertexPosition, 1.0);
    vec3 pos = p.xyz / p.w;
    vec3 n = normalize (uNormalMatrix * aVertexNormal);
    vec3 l = normalize (uLightPosition - pos);
    float nl = max (dot (n, l), 0.0);
    vDiffuse = 0.2 + nl * uLightColor;
    vSpecular = vec3 (0.0);
    if (nl > 0.0)
        vSpecular = pow (max (dot (reflect (-l, n), normalize (-pos)), 0.0), 10.0) * uLightColor
                    * vec3 (0.4);
    vColor = aVertexColor;
    vTextureCoord = aVertexTextureCoord;
    gl_Position = uProjectionMatrix * p;
}
