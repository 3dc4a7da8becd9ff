#version 330 core
// Padrob viewport, lit at the vertices: the pixel takes the blend of its triangle's
// vertex colours (viewport_vertex.vert).
in vec3 vColor;

uniform float uAlpha;

out vec4 fragColor;

void main()
{
    fragColor = vec4(vColor, uAlpha);
}
