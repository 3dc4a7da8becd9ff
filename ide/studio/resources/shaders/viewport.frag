#version 330 core
// Padrob viewport, lit at every pixel: shade() is lighting.glsl's, which the viewport
// puts here, after the #version line.
in vec3 vNormal;
in vec3 vColor;
in vec3 vEye;
in vec3 vWorld;

uniform int uLit;            // 0: flat colour (grid lines, lamps)
uniform vec4 uTint;          // rgb, and how much of it replaces the colour (highlight)
uniform float uAlpha;
uniform vec2 uFadeCentre;    // grid fade: centre (world x, y)
uniform float uFadeRadius;   // 0: no fade

out vec4 fragColor;

void main()
{
    vec3 base = mix(vColor, uTint.rgb, uTint.a);
    vec3 color = uLit != 0 ? shade(base, vNormal, vEye) : base;
    float alpha = uAlpha;
    if (uFadeRadius > 0.0) {
        float d = length(vWorld.xy - uFadeCentre);
        alpha *= 1.0 - smoothstep(0.5 * uFadeRadius, uFadeRadius, d);
    }
    fragColor = vec4(color, alpha);
}
