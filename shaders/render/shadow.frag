// Shadow-map pass, fragment stage: alpha-masked texels cast no shadow; cube-map faces store
// distance to the light / far, so one comparison works across all six faces.
#include "../common/shared.h"

layout(std430, binding = BIND_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

#include "../common/material.glsl"

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;
layout(location = LOC_SHADOW_LIGHT_POSITION) uniform vec4 lightPositionAndFar;

in ShadowVertex {
    vec3 position;
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
    if (lightPositionAndFar.w > 0.0) {
        gl_FragDepth = length(vin.position - lightPositionAndFar.xyz) / lightPositionAndFar.w;
    } else {
        gl_FragDepth = gl_FragCoord.z;
    }
}
