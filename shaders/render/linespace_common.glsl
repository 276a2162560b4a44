// What the line-space build passes share: the N-tree's header, its occupancy bits per level
// (BIND_SSBO_LINESPACE_OCCUPANCY) and the flat invocation index of a dispatch that may span
// two dimensions of groups (more than 65535 groups).
#ifndef GI_LINESPACE_COMMON_GLSL
#define GI_LINESPACE_COMMON_GLSL

#include "../common/shared.h"

layout(local_size_x = LINESPACE_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_LINESPACE_NODES) buffer LineSpaceNodeBlock {
    GpuLineSpaceHeader lineSpace;
    uint lineSpaceChildren[];
};

layout(std430, binding = BIND_SSBO_LINESPACE_OCCUPANCY) buffer LineSpaceOccupancyBlock {
    uint occupancy[];
};

uint flatGroup() {
    return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}

uint flatInvocation() {
    return flatGroup() * uint(LINESPACE_LOCAL_SIZE) + gl_LocalInvocationID.x;
}

uint levelResolution(int level) {
    uint r = 1u;
    for (int i = 0; i < level; ++i) r *= uint(lineSpace.shape.x);
    return r;
}

// Where level `level`'s bits start, in uints (as LineSpaceLayout::occupancyOffset).
uint levelOffset(int level) {
    uint words = 0u;
    for (int l = 0; l < level; ++l) {
        uint r = levelResolution(l);
        words += (r * r * r + 31u) / 32u;
    }
    return words;
}

bool occupied(uint offset, uint r, uvec3 cell) {
    uint i = cell.x + r * (cell.y + r * cell.z);
    return ((occupancy[offset + (i >> 5)] >> (i & 31u)) & 1u) != 0u;
}

void markOccupied(uint offset, uint r, uvec3 cell) {
    uint i = cell.x + r * (cell.y + r * cell.z);
    atomicOr(occupancy[offset + (i >> 5)], 1u << (i & 31u));
}

#endif
