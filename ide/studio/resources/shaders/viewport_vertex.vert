#version 330 core
// Padrob viewport, lit at the vertices (Gouraud shading), for software OpenGL
// (llvmpipe), where a frame's cost is its pixels': the light is computed here, once a
// vertex, and each pixel only takes its triangle's blend of it (viewport_vertex.frag).
// shade() is lighting.glsl's, which the viewport puts here, after the #version line.
// Large faces are cut into a grid (MeshBuilder::setMaxEdge), so that a lamp's pool of
// light still shows across them. No grid fade: the grid is drawn with viewport.frag.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uModel;         // body frame -> world
uniform mat4 uView;          // world -> eye
uniform mat4 uProjection;    // eye -> clip
uniform mat3 uNormalMatrix;  // inverse transpose of (view * model), upper 3x3
uniform vec4 uClipPlane;     // eye space: drawn where dot(uClipPlane, eye) >= 0 (when enabled)
uniform int uLit;            // 0: flat colour (lamps)
uniform vec4 uTint;          // rgb, and how much of it replaces the colour (highlight)

out vec3 vColor;  // lit

void main()
{
    vec4 eye = uView * (uModel * vec4(aPosition, 1.0));
    vec3 base = mix(aColor, uTint.rgb, uTint.a);
    vColor = uLit != 0 ? shade(base, uNormalMatrix * aNormal, eye.xyz) : base;
    gl_ClipDistance[0] = dot(uClipPlane, eye);
    gl_Position = uProjection * eye;
}
