// Padrob viewport: the light on a surface, shared by the two ways of shading. The
// viewport puts this after the #version line of viewport.frag (lit at every pixel) or
// of viewport_vertex.vert (lit at the vertices, for software OpenGL), with LAMP_COUNT
// defined (0 … 4): one program per count, so that the loop over the lamps is unrolled
// and llvmpipe no longer indexes uLightEye per pixel.
//
// Key light from the upper left, a cool fill from the right, and a hemisphere ambient
// (brighter from the sky) so that faces turned differently read differently: the
// daylight, dimmed inside a scene with lamps, whose point lights then add up. The side
// facing the viewer is lit, whatever the triangles' winding.
#ifndef LAMP_COUNT
#define LAMP_COUNT 0
#endif
uniform vec3 uUpEye;         // world up (z) in eye space
uniform float uDaylight;     // 1 outdoors; less inside a scene with lamps
uniform vec3 uLightEye[4];   // the point lights' (lamps') positions, eye space; LAMP_COUNT of them
uniform vec3 uLightColor;
uniform float uLightRange;   // a lamp lights half as much this far away [m]

// `base` lit at the eye-space point `eye` with the normal `normal` (any length)
vec3 shade(vec3 base, vec3 normal, vec3 eye)
{
    vec3 n = normalize(normal);
    vec3 v = normalize(-eye);
    if (dot(n, v) < 0.0) n = -n;
    vec3 key = normalize(vec3(-0.45, 0.60, 0.66));
    vec3 fill = normalize(vec3(0.75, -0.15, 0.45));
    float hemi = 0.5 + 0.5 * dot(n, normalize(uUpEye));
    vec3 ambient = mix(vec3(0.16, 0.15, 0.14), vec3(0.30, 0.31, 0.34), hemi);
    float diffuse = 0.70 * max(dot(n, key), 0.0);
    vec3 fillLight = vec3(0.22, 0.24, 0.28) * max(dot(n, fill), 0.0);
    vec3 h = normalize(key + v);
    // pow(x, 40) as x^32 · x^8: llvmpipe's pow is a log2 and an exp2 per pixel
    float x = max(dot(n, h), 0.0);
    float x2 = x * x;
    float x4 = x2 * x2;
    float x8 = x4 * x4;
    float x16 = x8 * x8;
    float x32 = x16 * x16;
    float specular = 0.20 * (x32 * x8);
    vec3 light = uDaylight * (ambient + vec3(diffuse) + fillLight);
    vec3 shine = vec3(uDaylight * specular);
    // the lamps: diffuse only, fading with the square of the distance
    float range2 = uLightRange * uLightRange;
    for (int i = 0; i < LAMP_COUNT; ++i) {
        vec3 d = uLightEye[i] - eye;
        float r2 = dot(d, d);
        float lit = max(dot(n, d), 0.0) * inversesqrt(max(r2, 1e-8));
        light += uLightColor * (lit * range2 / (range2 + r2));
    }
    return base * light + shine;
}
