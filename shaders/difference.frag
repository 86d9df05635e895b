#version 330 core
// |A - B| as a heat map: the largest channel difference, 0 (black) to uScale (white) through
// blue, red and yellow; above uScale it stays white. A colour scale runs up the right edge.
in vec2 fUV;

uniform sampler2D uA;
uniform sampler2D uB;
uniform float uScale;   // the difference, 0 to 1, shown as the top of the scale
uniform vec2 uPixels;   // the viewport's size in pixels
uniform vec4 uBar;      // the colour scale: left, bottom, right, top in pixels (differenceScaleBar)

out vec4 fragColor;

vec3 heat(float t)
{
    t = clamp(t, 0.0, 1.0);
    vec3 c = mix(vec3(0.0), vec3(0.1, 0.2, 0.9), smoothstep(0.0, 0.25, t));
    c = mix(c, vec3(0.9, 0.1, 0.1), smoothstep(0.25, 0.5, t));
    c = mix(c, vec3(1.0, 0.9, 0.1), smoothstep(0.5, 0.75, t));
    return mix(c, vec3(1.0), smoothstep(0.75, 1.0, t));
}

void main()
{
    vec2 px = fUV * uPixels;
    // The colour scale, where the viewport writes its numbers (its width follows the UI scale).
    float barLeft = uBar.x, barBottom = uBar.y, barRight = uBar.z, barTop = uBar.w;
    if (px.x >= barLeft - 1.0 && px.x <= barRight + 1.0 && px.y >= barBottom - 1.0 &&
        px.y <= barTop + 1.0) {
        bool frame = px.x < barLeft || px.x > barRight || px.y < barBottom || px.y > barTop;
        fragColor = vec4(frame ? vec3(0.8) : heat((px.y - barBottom) / (barTop - barBottom)),
                         1.0);
        return;
    }
    vec3 d = abs(texture(uA, fUV).rgb - texture(uB, fUV).rgb);
    float largest = max(d.r, max(d.g, d.b));
    fragColor = vec4(heat(largest / uScale), 1.0);
}
