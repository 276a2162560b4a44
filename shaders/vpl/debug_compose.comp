// The VPL debug views, step 2, one invocation per pixel:
//   VPL_DEBUG_POINTS, VPL_DEBUG_SUBSET: the surfaces in grey (brighter where they face the
//     eye), and over them the VPL splatted at each pixel (debug_splat.comp) in the colour of its
//     flux scaled to a largest channel of 1 (every VPL carries the same r + g + b flux, so the
//     colour is the light it reflects); VPLs outside the highlighted subset in mid grey;
//   VPL_DEBUG_VISIBILITY: the mean visibility of the VPLs facing each surface (the gather run
//     with VPL_GATHER_VISIBLE_FRACTION, merged over the tile by the filter), 1 white.
// Alpha: 1 on surfaces and VPLs, 0 on the background.
#include "vpl_common.glsl"
#include "../common/frame.glsl"

layout(local_size_x = VPL_LOCAL_SIZE, local_size_y = VPL_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_VPLS) readonly buffer VplBlockData {
    GpuVpl vpls[];
};

layout(binding = BIND_IMG_VPL_DEBUG_IDS, r32ui) uniform readonly uimage2D ids;
layout(binding = BIND_TEX_VPL_GATHERED) uniform sampler2D merged;
layout(binding = BIND_IMG_VPL_DEBUG_TARGET, rgba32f) writeonly uniform image2D target;
layout(location = LOC_VPL_DEBUG_VIEW) uniform int view;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(target);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 position = texelFetch(gPosition, pixel, 0);
    bool surface = position.w > 0.0;
    if (view == VPL_DEBUG_VISIBILITY) {
        float visible = surface ? texelFetch(merged, pixel, 0).r : 0.0;
        imageStore(target, pixel, vec4(vec3(visible), surface ? 1.0 : 0.0));
        return;
    }
    vec3 colour = vec3(0.0);
    if (surface) {
        vec3 n = texelFetch(gNormal, pixel, 0).xyz;
        vec3 toEye = normalize(frame.cameraPosition.xyz - position.xyz);
        colour = vec3(0.06 + 0.2 * max(dot(n, toEye), 0.0));
    }
    uint key = imageLoad(ids, pixel).r;
    if (key != 0u) {
        vec3 flux = vpls[int(key & 0x7fffffffu) - 1].flux.rgb;
        vec3 hue = flux / max(max(flux.r, max(flux.g, flux.b)), 1e-30);
        colour = (key & 0x80000000u) != 0u ? hue : vec3(0.45);
    }
    imageStore(target, pixel, vec4(colour, surface || key != 0u ? 1.0 : 0.0));
}
