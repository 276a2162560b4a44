// Depth pre-pass shared by every pass that shades each visible surface once: alpha-masked
// texels are cut out, everything else only writes depth. The shading pass then runs with
// an early LEQUAL test against it (its vertex stage declares gl_Position invariant).
#include "shared.h"

layout(std430, binding = BIND_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

#include "material.glsl"

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

in VertexData {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
} vin;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (m.flags.z == ALPHA_MASK) {
        vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
        if (materialCutOut(m, baseColor.a)) discard;
    }
}
