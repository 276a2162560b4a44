// The VPL debug views, step 1: each VPL the camera sees is splatted as a disc into an id
// image, one invocation per VPL. Discs overlap, so each pixel keeps the largest key by an
// atomic max: a highlighted VPL (bit 31) wins over the others, then the higher index, so the
// picture does not depend on the order the invocations run in.
#include "vpl_common.glsl"
#include "../common/frame.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = BIND_SSBO_VPLS) readonly buffer VplBlockData {
    GpuVpl vpls[];
};

layout(binding = BIND_IMG_VPL_DEBUG_IDS, r32ui) uniform coherent uimage2D ids;
layout(location = LOC_VPL_DEBUG_HIGHLIGHT) uniform int highlightClass;
layout(location = LOC_VPL_DEBUG_RADIUS) uniform int radius;

// A VPL lies on a surface: it is seen when it is no farther than the surface its pixel shows.
const float kDepthTolerance = 0.02;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= vpl.counts.x) return;
    vec3 p = vpls[i].position.xyz;
    vec4 clip = frame.viewProjection * vec4(p, 1.0);
    if (clip.w <= 0.0) return;
    ivec2 size = imageSize(ids);
    ivec2 centre = ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * vec2(size)));
    if (any(lessThan(centre, ivec2(0))) || any(greaterThanEqual(centre, size))) return;
    float depth = -(frame.view * vec4(p, 1.0)).z;
    float seen = texelFetch(gPosition, centre, 0).w;
    if (seen > 0.0 && depth > seen * (1.0 + kDepthTolerance)) return;

    // The pixel class whose gather uses VPL i (gather.comp: i mod tile^2).
    int subsets = vpl.counts.y * vpl.counts.y;
    bool highlighted = highlightClass < 0 || i % subsets == highlightClass % subsets;
    uint key = (highlighted ? 0x80000000u : 0u) | uint(i + 1);
    int r = highlighted ? radius : max(radius / 2, 1);
    for (int y = -r; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            ivec2 q = centre + ivec2(x, y);
            if (x * x + y * y > r * r + r || any(lessThan(q, ivec2(0))) ||
                    any(greaterThanEqual(q, size))) {
                continue;
            }
            imageAtomicMax(ids, q, key);
        }
    }
}
