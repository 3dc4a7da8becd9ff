#version 330 core
// Dark grey, lighter towards the top.
in vec2 vUv;
uniform vec3 uBottom;
uniform vec3 uTop;
out vec4 fragColor;

void main()
{
    fragColor = vec4(mix(uBottom, uTop, vUv.y), 1.0);
}
