// VPL gather (SEEDS.md section 4): the indirect irradiance at the surface of each pixel is the
// light of every VPL, a Lambertian emitter of flux phi and radiant intensity phi/pi cos(theta_i):
//   E_ind(x) = sum_i phi_i / pi * V * max(0, cos theta_x) * max(0, cos theta_i) / max(B, r^2),
// B the clamp (vpl.clamp) that bounds the 1/r^2 spike of a VPL next to the receiver.
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

layout(binding = BIND_IMG_VPL_TARGET, rgba16f) writeonly uniform image2D target;

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
    vec3 e = vec3(0.0);
    float visible = 0.0, facing = 0.0;   // the vpl-visibility debug view's counts
    for (int i = first; i < vpl.counts.x; i += stride) {
        GpuVpl light = vpls[i];
        vec3 d = light.position.xyz - x;
        float r2 = dot(d, d);
        vec3 dir = d * inversesqrt(max(r2, 1e-20));
        float cosX = dot(n, dir);
        float cosI = -dot(light.normal.xyz, dir);
        if (cosX <= 0.0 || cosI <= 0.0) continue;
        float visibility = vplVisibility(x, n, light.position.xyz, light.normal.xyz);
        e += light.flux.rgb * (visibility * cosX * cosI / (PI * max(clampB, r2)));
        visible += visibility;
        facing += 1.0;
    }
    if (vpl.counts.w == VPL_GATHER_VISIBLE_FRACTION) {
        imageStore(target, pixel, vec4(vec3(visible / max(facing, 1.0)), position.w));
        return;
    }
    imageStore(target, pixel, vec4(min(e * vpl.gather.y, vec3(HALF_STORE_MAX)), position.w));
}
