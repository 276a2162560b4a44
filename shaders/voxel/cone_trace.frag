// Screen-space cone tracing (thesis 4.3.3.4): every visible surface point gathers its
// indirect irradiance E_ind (W/m^2, DESIGN.md) from 9 cones through the voxel cascade
// (cone_tracing.glsl: the cones, their weights and how they read the voxels).
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#include "cone_tracing.glsl"

// Tested against the depth pre-pass before shading: hidden surfaces trace no cones.
layout(early_fragment_tests) in;

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outIndirect;

// A strided trace (TraceReusePass.h) covers pixel (stride x + y, stride y + z) of the full
// trace with its pixel (x, y): the ring's dither follows the full trace's pixel.
layout(location = LOC_CONE_TRACE_PATTERN) uniform ivec3 tracePattern;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
    int level = finestLevel(vin.position);
    if (level < 0) {
        outIndirect = vec4(0.0, 0.0, 0.0, viewDepth);
        return;
    }
    vec3 n = normalize(vin.normal);
    // The side the viewer sees gathers, the side its own normal faces from the eye, as in the
    // path tracer and the forward pass (the winding picks the wrong side where normals point
    // against it).
    if (dot(n, frame.cameraPosition.xyz - vin.position) < 0.0) n = -n;
    // Leave the surface's own voxel before the first sample.
    vec3 origin = vin.position + n * levelVoxelSize(level);
    // With voxel.jitter the ring turns by a 4x4 ordered-dither fraction of its 45-degree
    // spacing, so neighbouring pixels sample 16 different ring directions; the filter pass
    // averages them back into a smooth result.
    float ringTurn = 0.0;
    if (voxel.smoothing.y != 0.0) {
        const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0,
                                          3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
        ivec2 cell = (ivec2(gl_FragCoord.xy) * tracePattern.x + tracePattern.yz) & 3;
        ringTurn = (bayer[cell.y * 4 + cell.x] + 0.5) / 16.0 * (PI / 4.0);
    }
    outIndirect = vec4(coneIrradiance(origin, n, ringTurn, voxel.trace.y), viewDepth);
}
