// Shadow-map pass, fragment stage: alpha-masked texels cast no shadow; cube-map faces store
// distance to the light / far, so one comparison works across all six faces.
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"

layout(location = LOC_SHADOW_LIGHT_POSITION) uniform vec4 lightPositionAndFar;

in VertexData { VERTEX_DATA_MEMBERS } vin;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    if (lightPositionAndFar.w > 0.0) {
        gl_FragDepth = length(vin.position - lightPositionAndFar.xyz) / lightPositionAndFar.w;
    } else {
        gl_FragDepth = gl_FragCoord.z;
    }
}
