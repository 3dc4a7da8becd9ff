#version 330 core
// A triangle that covers the screen (no vertex buffer), on the far plane: drawn after
// the solids with the depth test (less or equal), it fills only what they left empty.
out vec2 vUv;

void main()
{
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vUv = 0.5 * p + 0.5;
    gl_Position = vec4(p, 1.0, 1.0);
}
