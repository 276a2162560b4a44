// The sparse voxel octree of gi/vpl (SparseVoxelOctree.h): its cube and its node pool, as the
// build (shaders/vpl/svo_*.comp, SVO_BUILD defined) writes them and the march
// (svo_visibility.glsl) reads them. Node 0 is the root, the cube of 2^depth leaf voxels a side;
// a node is SVO_NODE_FLAG when its cube holds geometry, and a flagged node above the leaves
// points at its 8 children, which lie side by side: child x + 2y + 4z is the octant on the
// high side of the axes whose bit is set. Coordinates here are in leaf voxels from the cube's
// lowest corner.
#ifndef GI_SVO_GLSL
#define GI_SVO_GLSL

#include "shared.h"

layout(std140, binding = BIND_UBO_SVO) uniform SvoBlock {
    SvoUniforms svo;
};

#ifdef SVO_BUILD
#define SVO_NODE_ACCESS coherent
#else
#define SVO_NODE_ACCESS readonly
#endif

layout(std430, binding = BIND_SSBO_SVO_NODES) SVO_NODE_ACCESS buffer SvoNodeBlock {
    uint svoNodes[];
};

int svoResolution() { return svo.shape.x; }
int svoDepth() { return svo.shape.y; }

vec3 svoFromWorld(vec3 p) { return (p - svo.cube.xyz) / svo.cube.w; }

uint svoChildSlot(uvec3 octant) { return octant.x + 2u * octant.y + 4u * octant.z; }

uint svoPackLeaf(uvec3 leaf) {
    return leaf.x | (leaf.y << SVO_COORD_BITS) | (leaf.z << (2 * SVO_COORD_BITS));
}

uvec3 svoUnpackLeaf(uint word) {
    uint mask = (1u << SVO_COORD_BITS) - 1u;
    return uvec3(word, word >> SVO_COORD_BITS, word >> (2 * SVO_COORD_BITS)) & mask;
}

#endif
