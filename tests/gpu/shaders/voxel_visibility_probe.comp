// Runs shaders/common/voxel_visibility.glsl on hand-made segments (VoxelVisibilityGpuTest.cpp),
// one work group per case, against the voxel occupancy the test bound at the renderer's slots.
// The test binds its own two buffers at 0 and 1; no pass uses this.
#include "shaders/common/voxel_visibility.glsl"

layout(local_size_x = 1) in;

struct SegmentCase {
    vec4 receiver;   // xyz = world position (m)
    vec4 receiverNormal;
    vec4 sender;
    vec4 senderNormal;
};

layout(std430, binding = 0) readonly buffer Cases {
    SegmentCase cases[];
};
layout(std430, binding = 1) writeonly buffer Results {
    vec4 results[];   // x = transmittance
};

void main() {
    uint i = gl_WorkGroupID.x;
    SegmentCase c = cases[i];
    results[i] = vec4(voxelTransmittance(c.receiver.xyz, c.receiverNormal.xyz, c.sender.xyz,
            c.senderNormal.xyz), 0.0, 0.0, 0.0);
}
