// Octree voxel fragments, fragment stage: the leaf voxel holding the fragment is set in a
// bit grid, and the fragment that sets it appends the leaf to the fragment list, so the list
// holds every occupied leaf once (the octree's flag passes then walk each leaf once, not once
// per fragment). Alpha-masked texels are cut out as in every pass that draws the scene.
#include "../common/material.glsl"
#include "../common/svo.glsl"
#include "../common/vertex_data.glsl"

layout(std430, binding = BIND_SSBO_SVO_LEAF_BITS) coherent buffer SvoLeafBitsBlock {
    uint leafBits[];
};

layout(std430, binding = BIND_SSBO_SVO_FRAGMENTS) coherent buffer SvoFragmentBlock {
    uint fragmentCount;
    uint fragments[];
};

in VertexData { VERTEX_DATA_MEMBERS } vin;

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;
    vec3 p = svoFromWorld(vin.position);
    uint r = uint(svoResolution());
    if (any(lessThan(p, vec3(0.0))) || any(greaterThanEqual(p, vec3(r)))) discard;
    uvec3 leaf = min(uvec3(p), uvec3(r - 1u));
    uint bit = leaf.x + r * (leaf.y + r * leaf.z);
    uint mask = 1u << (bit & 31u);
    if ((atomicOr(leafBits[bit >> 5], mask) & mask) != 0u) return;
    uint slot = atomicAdd(fragmentCount, 1u);
    if (slot < uint(fragments.length())) fragments[slot] = svoPackLeaf(leaf);
}
