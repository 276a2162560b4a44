// Runs shaders/common/voxel_plane.glsl on hand-made cases (VoxelPlaneGpuTest.cpp), one
// invocation per case. The test binds its own two buffers at 0 and 1; no pass uses this.
#include "shaders/common/voxel_plane.glsl"

layout(local_size_x = 1) in;

struct PlaneCase {
    vec4 plane;    // the normal texel: xyz = mean normal, w = offset in voxel sizes
    vec4 voxel;    // xyz = centre, w = edge size
    vec4 a;        // xyz = segment start, w = tolerance (< 0: kPlaneTolerance)
    vec4 b;        // xyz = segment end, w = level
};

layout(std430, binding = 0) readonly buffer Cases {
    PlaneCase cases[];
};
layout(std430, binding = 1) writeonly buffer Results {
    ivec4 results[];   // x = one plane, y = one plane counting coarser levels, z = crosses
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    PlaneCase c = cases[i];
    int level = int(c.b.w);
    float tolerance = c.a.w < 0.0 ? kPlaneTolerance : c.a.w;
    bool crosses = segmentCrossesVoxelPlane(c.plane, c.voxel.xyz, c.voxel.w, c.a.xyz, c.b.xyz,
            tolerance);
    results[i] = ivec4(voxelHoldsOnePlane(c.plane, level, false),
            voxelHoldsOnePlane(c.plane, level, true), crosses, 0);
}
