// Toon shading: the diffuse term in a few flat bands, a hard-edged highlight and a dark
// rim where the surface turns away from the eye. bands and rimWidth are not panel values:
// the workbench makes a control for each of them.
precision mediump float;

varying vec3 fPosition;
varying vec3 fNormal;
varying vec3 fLight;

uniform vec3 lightAmb;
uniform vec3 lightDif;
uniform vec3 lightSpe;
uniform vec3 materialAmb;
uniform vec3 materialDif;
uniform vec3 materialSpe;
uniform float shininess;

uniform float bands;    // how many diffuse bands (try 2 to 5)
uniform float rimWidth; // 0 = no outline, 0.4 = a thick one

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
    gl_FragColor = vec4(mix(colour, vec3(0.05), rim), 1.0);
}
