// Edge-aware smoothing of the traced indirect irradiance (the thesis' future work: "filtering
// and smart interpolation of the indirect result"): each texel becomes the mean of its
// (2r+1)^2 neighbourhood, every neighbour weighted by how close its view depth is to the
// centre's, so light does not cross depth edges. With the cone ring's jitter, the
// neighbourhood holds a whole period of its turns (gi/voxel/RingDither.h: 4 or 16 different
// rings): the mean behaves like many more cones.
//
// A group first copies the texels its windows cover into shared memory, and IndirectFilterPass
// builds the program per radius (FILTER_RADIUS), so the window's loops have constant bounds:
// on llvmpipe the two together made the full-resolution filter x0.73 (results-performance.md).
// The variant-free program reads the radius from the voxel uniforms.
#include "../common/voxel_cascade.glsl"

layout(local_size_x = VOXEL_FILTER_LOCAL_SIZE, local_size_y = VOXEL_FILTER_LOCAL_SIZE) in;

layout(binding = BIND_TEX_FILTER_SOURCE) uniform sampler2D source;
layout(binding = BIND_IMG_FILTER_TARGET, rgba16f) writeonly uniform image2D target;

#ifdef FILTER_RADIUS
const int kTileRadius = FILTER_RADIUS;
int filterRadius() { return FILTER_RADIUS; }
#else
const int kTileRadius = VOXEL_FILTER_MAX_RADIUS;
int filterRadius() { return min(int(voxel.smoothing.x), kTileRadius); }
#endif

// The group's texels and kTileRadius around them; texels outside the image are empty (a = 0).
const int kTile = VOXEL_FILTER_LOCAL_SIZE + 2 * kTileRadius;
shared vec4 tile[kTile * kTile];

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(source, 0);
    ivec2 corner = ivec2(gl_WorkGroupID.xy) * VOXEL_FILTER_LOCAL_SIZE - kTileRadius;
    for (int i = int(gl_LocalInvocationIndex); i < kTile * kTile;
            i += VOXEL_FILTER_LOCAL_SIZE * VOXEL_FILTER_LOCAL_SIZE) {
        ivec2 p = corner + ivec2(i % kTile, i / kTile);
        bool inside = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size));
        tile[i] = inside ? texelFetch(source, p, 0) : vec4(0.0);
    }
    barrier();
    if (any(greaterThanEqual(texel, size))) return;
    ivec2 local = ivec2(gl_LocalInvocationID.xy) + kTileRadius;
    vec4 centre = tile[local.y * kTile + local.x];
    if (centre.a <= 0.0) {
        imageStore(target, texel, centre);
        return;
    }
    int radius = filterRadius();
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            vec4 t = tile[(local.y + y) * kTile + local.x + x];
            if (t.a <= 0.0) continue;
            float relative = abs(t.a - centre.a) / centre.a;
            float w = exp(-relative * relative * 2000.0);
            sum += w * t.rgb;
            weightSum += w;
        }
    }
    imageStore(target, texel, vec4(sum / weightSum, centre.a));
}
