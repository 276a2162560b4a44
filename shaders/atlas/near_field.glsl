// The atlas gather's near field. The area estimator (gather.frag) weighs a sender texel by
// cos cos / max(r^2, B), B = (2 texel edges)^2: texels next to the receiver are not points,
// and their 1/r^2 would dominate its noise. So it leaves out part of the light of the senders
// within sqrt(B), and through the voxel occupancy's march it blocks much of what the senders
// within a voxel or two send (the march lets the voxels at its ends pass, and the voxels next
// to them hold the surfaces that meet the receiver's). Where two surfaces meet (a block on a
// sunlit floor, every corner of a room) most of the light a receiver near the edge gets comes
// from there. The near field counts every sender nearer than its reach instead (nearField.y,
// atlas.near_reach texel edges: by default three times sqrt(B)), and the area estimator skips
// them:
//   E_near(x) = integral over r < reach of L(y) cos(theta_x) cos(theta_y) / r^2 dA(y)
//             = integral over the hemisphere of L(y(w)) cos(theta_x) [r(w) < reach] dw,
// y(w) the first surface the receiver sees in direction w. Cosine-distributed directions
// estimate it as pi L(y(w)) for each that meets a surface within the reach: bounded at any
// distance. A ray through the scene's BVH finds y, the hit triangle's atlas coordinates the
// texel under it, whose radiance counts on the side the ray meets (none on the back of a
// one-sided surface). Both parts together weigh every sender by the whole kernel.
#ifndef GI_ATLAS_NEAR_FIELD_GLSL
#define GI_ATLAS_NEAR_FIELD_GLSL

#include "atlas_common.glsl"
#include "../common/bvh.glsl"
#include "../common/cosine_direction.glsl"
#include "../common/hash.glsl"

layout(std430, binding = BIND_SSBO_ATLAS_VERTICES) readonly buffer NearFieldAtlasVertices {
    float atlasVertexFloats[];
};
layout(std430, binding = BIND_SSBO_ATLAS_INDICES) readonly buffer NearFieldAtlasIndices {
    uint atlasIndices[];
};

// This draw's directions [x, y) of nearFieldDirections(), and z: the nodes a ray's walk may
// visit (within the draw's loop budget: AtlasGatherPass).
layout(location = LOC_ATLAS_NEAR_RANGE) uniform ivec4 nearRange;

// Directions per receiver side and set (atlas.near_rays); 0 leaves the near field out.
int nearFieldDirections() { return int(atlas.nearField.x); }

// The squared distance within which the near field, not the area estimator, counts a sender.
float nearFieldReach2() { return nearFieldDirections() > 0 ? atlas.nearField.y : 0.0; }

vec2 atlasUvOfVertex(uint v) {
    uint at = v * uint(ATLAS_VERTEX_FLOATS) + uint(ATLAS_VERTEX_UV_OFFSET);
    return vec2(atlasVertexFloats[at], atlasVertexFloats[at + 1u]);
}

// The atlas texel under the point (1 - u - v) a + u b + v c of scene triangle `triangle`.
ivec2 atlasTexelOf(int triangle, vec2 uv, int resolution) {
    uint first = 3u * uint(triangle);
    vec2 p = (1.0 - uv.x - uv.y) * atlasUvOfVertex(atlasIndices[first]) +
             uv.x * atlasUvOfVertex(atlasIndices[first + 1u]) +
             uv.y * atlasUvOfVertex(atlasIndices[first + 2u]);
    return clamp(ivec2(p * float(resolution)), ivec2(0), ivec2(resolution - 1));
}

// This draw's share of E_near on the side of the receiver at x facing n (unit), for texels of
// surface area `area`.
vec3 nearFieldIrradiance(vec3 x, vec3 n, float area, uint seed, sampler2D front, sampler2D back,
        sampler2D normals) {
    int directions = nearFieldDirections();
    float reach2 = nearFieldReach2();
    if (directions <= 0 || nearRange.x >= nearRange.y || !(reach2 > 0.0)) return vec3(0.0);
    float reach = sqrt(reach2);
    // Off the receiver's own surface by a thousandth of a texel edge, far less than any
    // distance the kernel tells apart, and each ray from half that behind it: a texel whose
    // centre lies on the edge where its surface meets another (the atlas' charts put texel
    // centres on their borders) sees that surface from a distance of zero, which a ray
    // starting on it would not meet.
    float offset = 1e-3 * sqrt(max(area, 0.0));
    vec3 origin = x + n * offset;
    int resolution = atlas.size.x;
    vec3 sum = vec3(0.0);
    for (int i = nearRange.x; i < nearRange.y; ++i) {
        vec3 w = stratifiedCosineDirection(n, i, directions, seed);
        int corner;
        vec3 hit = bvhWalk(origin - w * (0.5 * offset), w, reach + 0.5 * offset, true, nearRange.z,
                corner);
        if (hit.x <= 0.0) continue;
        ivec2 t = atlasTexelOf(floatBitsToInt(bvhTriangles[corner].w), hit.yz, resolution);
        vec4 radiance = texelFetch(front, t, 0);
        if (radiance.a <= 0.0) continue;
        vec4 normal = texelFetch(normals, t, 0);
        bool metFront = dot(normal.xyz, w) < 0.0;
        if (!metFront) {
            if (normal.w <= 0.5) continue;
            radiance = texelFetch(back, t, 0);
        }
        sum += radiance.rgb;
    }
    return PI * sum / float(directions);
}

#endif
