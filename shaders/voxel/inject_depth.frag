// Light injection, depth pre-pass: alpha-masked texels are cut out, everything else only
// writes depth. Without this pass the early depth test of inject.frag would depend on draw
// order (a fragment drawn before its occluder would still inject light).
#include "voxel_common.glsl"

layout(std430, binding = BIND_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

#include "../common/material.glsl"

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

in InjectVertex {
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
