// Camera G-buffer of the VPL gather: the visible surface's position, view depth and normal on
// the side the eye sees (the side the forward pass lights, as the path tracer does).
#include "../common/frame.glsl"
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"

layout(early_fragment_tests) in;

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    vec3 n = normalize(vin.normal);
    if (dot(n, frame.cameraPosition.xyz - vin.position) < 0.0) n = -n;
    float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
    outPosition = vec4(vin.position, max(viewDepth, 1e-6));
    outNormal = vec4(n, 1.0);
}
