// The lecture's Gouraud fragment shader, as printed (WebGL 1).
precision mediump float;

varying vec4 fColor;

void main() {
    gl_FragColor = fColor;
}
