#version 330 core
// Toon shading: the diffuse term in a few flat bands, a hard-edged highlight and a dark rim
// where the surface turns away from the eye. bands, rimWidth and outlineColour are not panel
// values: the workbench makes a control for each (Shader uniforms), starting from the
// initializers below.
in vec3 fPosition;
in vec3 fNormal;
in vec3 fLight;

uniform vec3 lightAmb;
uniform vec3 lightDif;
uniform vec3 lightSpe;
uniform vec3 materialAmb;
uniform vec3 materialDif;
uniform vec3 materialSpe;
uniform float shininess;

uniform float bands = 3.0;                  // how many diffuse bands
uniform float rimWidth = 0.35;              // 0: no outline
uniform vec3 outlineColour = vec3(0.05, 0.03, 0.02);

out vec4 fragColor;

void main()
{
    vec3 N = normalize(fNormal);
    vec3 L = normalize(fLight);
    vec3 V = normalize(-fPosition);
    vec3 H = normalize(L + V);

    float n = max(bands, 1.0);
    float diffuse = ceil(max(dot(L, N), 0.0) * n) / n;
    float highlight = step(0.5, pow(max(dot(N, H), 0.0), shininess));
    if (dot(L, N) < 0.0)
        highlight = 0.0;
    float rim = step(1.0 - rimWidth, 1.0 - max(dot(N, V), 0.0));

    vec3 colour = lightAmb * materialAmb + diffuse * lightDif * materialDif
                + highlight * lightSpe * materialSpe;
    fragColor = vec4(mix(colour, outlineColour, rim), 1.0);
}
