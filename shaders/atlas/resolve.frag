// Atlas resolve (thesis 4.7): every pixel looks up the lit atlas of the side it sees
// (atlas_side.glsl) bilinearly at its surface's atlas coordinate, giving the screen-space
// E_ind (W/m^2) the GiOutputs contract asks for, and stores its view depth for the final
// pass's depth-aware lookup.
#include "../common/frame.glsl"
#include "../common/material.glsl"
#include "atlas_common.glsl"
#include "atlas_side.glsl"
#include "atlas_vertex.glsl"

layout(binding = BIND_TEX_ATLAS_LIT) uniform sampler2D atlasLit;
layout(binding = BIND_TEX_ATLAS_LIT_BACK) uniform sampler2D atlasLitBack;

in ResolveVertex { RESOLVE_VERTEX_MEMBERS } vin;

layout(location = 0) out vec4 outIndirect;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
    vec3 indirect = cameraSeesBack(vin.position, vin.normal, vin.doubleSided)
            ? texture(atlasLitBack, vin.atlasUv).rgb
            : texture(atlasLit, vin.atlasUv).rgb;
    outIndirect = vec4(indirect, viewDepth);
}
