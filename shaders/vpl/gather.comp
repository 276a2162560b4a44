// VPL gather (SEEDS.md section 4): the indirect irradiance at the surface of each pixel is the
// light of every VPL, a Lambertian emitter of flux phi and radiant intensity phi/pi cos(theta_i):
//   E_ind(x) = sum_i phi_i / pi * V * max(0, cos theta_x) * max(0, cos theta_i) / max(B, r^2),
// B the clamp (vpl.clamp) that bounds the 1/r^2 spike of a VPL next to the receiver: by default
// the larger of the mean VPL's and one in proportion to the surface it stands for
// (gi/vpl/VplGi.h).
// Interleaved sampling (Keller and Heidrich 2001): pixel (x, y) uses only the VPLs of its
// subset (x mod t) + t (y mod t) and scales them by t^2; the filter merges the t x t
// neighbourhood, which holds every subset once.
#include "vpl_common.glsl"
#include "vpl_visibility.glsl"
#include "../common/constants.glsl"

layout(local_size_x = VPL_LOCAL_SIZE, local_size_y = VPL_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_VPLS) readonly buffer VplBlockData {
    GpuVpl vpls[];
};

// Each pixel's subset is split over dispatches that each stay within SHADER_LOOP_ITERATIONS
// (VplGatherPass): this one adds the subset's VPLs [x, y) to what the earlier ones stored;
// z = 1 on the last, which stores the result (the visible fraction's counts, until then).
layout(location = LOC_VPL_GATHER_RANGE) uniform ivec3 gatherRange;

// 32-bit floats: the dispatches' sums add up without half-float rounding at each store.
layout(binding = BIND_IMG_VPL_TARGET, rgba32f) uniform image2D target;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(gPosition, 0);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 position = texelFetch(gPosition, pixel, 0);
    if (position.w <= 0.0) {
        imageStore(target, pixel, vec4(0.0));
        return;
    }
    vec3 x = position.xyz;
    vec3 n = texelFetch(gNormal, pixel, 0).xyz;
    int tile = vpl.counts.y;
    int stride = tile * tile;
    ivec2 inTile = pixel % tile;
    int first = inTile.x + tile * inTile.y;
    float clampB = vpl.gather.x;
    bool firstRange = gatherRange.x == 0, lastRange = gatherRange.z != 0;
    vec4 earlier = firstRange ? vec4(0.0) : imageLoad(target, pixel);
    bool fraction = vpl.counts.w == VPL_GATHER_VISIBLE_FRACTION;
    // Sums so far: E_ind (scaled by vpl.gather.y as stored), or the debug view's counts.
    vec3 e = fraction ? vec3(0.0) : earlier.rgb / vpl.gather.y;
    float visible = fraction ? earlier.r : 0.0, facing = fraction ? earlier.g : 0.0;
    int end = min(vpl.counts.x, first + gatherRange.y * stride);
    for (int i = first + gatherRange.x * stride; i < end; i += stride) {
        GpuVpl light = vpls[i];
        vec3 d = light.position.xyz - x;
        float r2 = dot(d, d);
        vec3 dir = d * inversesqrt(max(r2, 1e-20));
        float cosX = dot(n, dir);
        float cosI = -dot(light.normal.xyz, dir);
        if (cosX <= 0.0 || cosI <= 0.0) continue;
        float visibility = vplVisibility(x, n, light.position.xyz, light.normal.xyz);
        // A VPL standing for more surface than the mean (one the view's importance drew
        // sparsely, carrying more flux) is cut where it no longer stands for its own.
        float b = max(clampB, vpl.rays.y * light.flux.w);
        e += light.flux.rgb * (visibility * cosX * cosI / (PI * max(b, r2)));
        visible += visibility;
        facing += 1.0;
    }
    if (fraction) {
        imageStore(target, pixel, lastRange ? vec4(vec3(visible / max(facing, 1.0)), position.w)
                                            : vec4(visible, facing, 0.0, position.w));
        return;
    }
    imageStore(target, pixel, vec4(min(e * vpl.gather.y, vec3(HALF_STORE_MAX)), position.w));
}
