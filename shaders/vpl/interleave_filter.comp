// Merges the interleaved subsets (SEEDS.md section 4): each pixel averages the t x t window
// around it that holds every VPL subset once, keeping only neighbours on the same surface
// (view depth within a fraction of the centre's, normals within an angle), so light does not
// cross depth edges or corners. A rejected neighbour's subset is missing from the mean: the
// other subsets stand in for it.
#include "vpl_common.glsl"

layout(local_size_x = VPL_LOCAL_SIZE, local_size_y = VPL_LOCAL_SIZE) in;

layout(binding = BIND_TEX_VPL_GATHERED) uniform sampler2D gathered;
layout(binding = BIND_IMG_VPL_TARGET, rgba16f) writeonly uniform image2D target;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(gathered, 0);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 centre = texelFetch(gathered, pixel, 0);
    int tile = vpl.counts.y;
    if (centre.a <= 0.0 || tile <= 1) {
        imageStore(target, pixel, centre);
        return;
    }
    vec3 normal = texelFetch(gNormal, pixel, 0).xyz;
    float depthTolerance = vpl.gather.z * centre.a;
    float normalCosine = vpl.gather.w;
    // The window starts tile/2 before the pixel; at the image's edges it slides inwards so
    // it still holds t x t pixels, every subset once.
    ivec2 lo = clamp(pixel - ivec2(tile / 2), ivec2(0), max(size - ivec2(tile), ivec2(0)));
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int y = 0; y < tile; ++y) {
        for (int x = 0; x < tile; ++x) {
            ivec2 p = min(lo + ivec2(x, y), size - 1);
            vec4 t = texelFetch(gathered, p, 0);
            if (t.a <= 0.0 || abs(t.a - centre.a) > depthTolerance) continue;
            if (dot(texelFetch(gNormal, p, 0).xyz, normal) < normalCosine) continue;
            sum += t.rgb;
            count += 1.0;
        }
    }
    imageStore(target, pixel, vec4(sum / max(count, 1.0), centre.a));
}
