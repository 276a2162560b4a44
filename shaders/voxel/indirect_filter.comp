// Edge-aware smoothing of the traced indirect irradiance (the thesis' future work: "filtering
// and smart interpolation of the indirect result"): each texel becomes the mean of its
// (2r+1)^2 neighbourhood, every neighbour weighted by how close its view depth is to the
// centre's, so light does not cross depth edges, and by how close it lies to the centre's
// plane, so light does not cross the edges where two surfaces meet at one depth (a block's
// top and its front, a wall and the ceiling): the depth alone let the filter carry a lit
// top face's light over its front's first rows and darken the top's edge, most in the
// quality preset's wide window (accuracy-analysis.md). With the cone ring's jitter, the
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

// How sharply a neighbour's distance from the centre's plane (relative to the centre's depth)
// lowers its weight: e^-1 at 0.003, ten times the error of a plane fitted through half-float
// depths (11-bit mantissa) a few texels out.
const float kPlaneSharpness = 1e5;
// The same for the view depth alone (e^-1 at 2 %).
const float kDepthSharpness = 2000.0;

// The gradient of 1/depth, which is affine in screen space over a plane, at the tile's texel
// `local` of inverse depth `inverse`: on each axis the one-sided difference towards the
// neighbour that continues it best, the side of the centre's own surface. (Choosing the side
// that goes on straightest over two texels read the half-float depths' rounding as bends:
// the quality preset's boxes 0.005-0.008 further from the path tracer.)
vec2 inverseDepthSlope(ivec2 local, float inverse) {
    vec2 slope = vec2(0.0);
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 step = ivec2(1 - axis, axis);
        vec4 before = tile[(local.y - step.y) * kTile + local.x - step.x];
        vec4 after = tile[(local.y + step.y) * kTile + local.x + step.x];
        float down = before.a > 0.0 ? inverse - 1.0 / before.a : 1e30;
        float up = after.a > 0.0 ? 1.0 / after.a - inverse : 1e30;
        float nearer = abs(down) < abs(up) ? down : up;
        slope[axis] = abs(nearer) < 1e29 ? nearer : 0.0;   // no neighbour: flat
    }
    return slope;
}

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
    float inverse = 1.0 / centre.a;
    vec2 slope = inverseDepthSlope(local, inverse);
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            vec4 t = tile[(local.y + y) * kTile + local.x + x];
            if (t.a <= 0.0) continue;
            float depth = abs(t.a - centre.a) / centre.a;
            float plane = abs(1.0 / t.a - (inverse + dot(slope, vec2(x, y)))) / inverse;
            float w = exp(-depth * depth * kDepthSharpness - plane * plane * kPlaneSharpness);
            sum += w * t.rgb;
            weightSum += w;
        }
    }
    imageStore(target, texel, vec4(sum / weightSum, centre.a));
}
