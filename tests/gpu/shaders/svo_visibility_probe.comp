// Runs shaders/common/svo_visibility.glsl on hand-made segments (SvoGpuTest.cpp), one
// invocation per case, against the octree the test bound at the renderer's slots. The test
// binds its own two buffers at 0 and 1; no pass uses this.
#include "shaders/common/svo_visibility.glsl"

layout(local_size_x = 1) in;

struct SegmentCase {
    vec4 receiver;          // xyz = world position (m)
    vec4 receiverNormal;
    vec4 light;             // xyz = the VPL's world position (m)
    vec4 lightNormal;
};

layout(std430, binding = 0) readonly buffer Cases {
    SegmentCase cases[];
};
layout(std430, binding = 1) writeonly buffer Results {
    vec4 results[];   // x = visibility
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    SegmentCase c = cases[i];
    results[i] = vec4(svoVisibility(c.receiver.xyz, c.receiverNormal.xyz, c.light.xyz,
            c.lightNormal.xyz), 0.0, 0.0, 0.0);
}
