#version 330 core
// Padrob viewport: every mesh (bodies, joints, grid, axes). Positions in the body
// frame, turned into the world by uModel; lighting is done in eye space.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uModel;       // body frame -> world
uniform mat4 uView;        // world -> eye
uniform mat4 uProjection;  // eye -> clip
uniform mat3 uNormalMatrix;  // inverse transpose of (view * model), upper 3x3
uniform vec4 uClipPlane;   // eye space: drawn where dot(uClipPlane, eye) >= 0 (when enabled)

out vec3 vNormal;  // eye space
out vec3 vColor;
out vec3 vEye;     // eye-space position
out vec3 vWorld;   // world position

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec4 eye = uView * world;
    vWorld = world.xyz;
    vEye = eye.xyz;
    vNormal = uNormalMatrix * aNormal;
    vColor = aColor;
    gl_ClipDistance[0] = dot(uClipPlane, eye);
    gl_Position = uProjection * eye;
}
