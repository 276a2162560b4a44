// Atlas gather (thesis 4.6, eq. 9), one fragment per atlas texel: the receiver x reads N
// sample texels y, skips pairs that do not face each other, and adds the sender's direct
// radiance L(y). Two estimators of
// E_ind(x) = integral of L(y) cos(theta_x) cos(theta_y) / r^2 dA(y):
//   ATLAS_ESTIMATOR_AREA      the area form, importance-sampled by the power each texel sends
//                             (by default, atlas.importance=surfaces, by that power times
//                             what the scene's surfaces, or with =view the camera's view, can
//                             receive of it: sender_weight.glsl; below, mean(L) and P then
//                             stand for the weight per area and its total):
//                             AtlasSenderSamplingPass draws texel y with probability
//                             p(y) = a(y) mean(L(y)) / P (a(y): the surface area the texel
//                             stands for, the position layer's w; P: the sum over all texels),
//                             so 1/N sum L(y) cos cos / r^2 a(y) / p(y)
//                             = P/N sum L(y) / mean(L(y)) cos(theta_x) cos(theta_y) / r^2
//                             estimates the integral (texels that send nothing are never drawn
//                             and add nothing to it). One point per stratum of equal power, the
//                             point within the stratum picked per receiver and set. r^2 is
//                             clamped at (2 texel edges)^2 (sampling.z): texels next to the
//                             receiver are not points, and their 1/r^2 spikes would dominate
//                             the error (Cornell box at 2048 samples: relative RMSE 0.52 with
//                             a one-texel clamp, 0.32 with two, for 0.2% less energy). With
//                             atlas.near_rays senders within the near field's reach
//                             (nearField.y, atlas.near_reach: by default three times the
//                             clamp's radius) are skipped here: rays count them, with the
//                             whole kernel (near_field.glsl).
//   ATLAS_ESTIMATOR_MERZ2010  sum L(y) cos(theta_x) * 2 pi / N over the Hammersley points of
//                             the atlas (rotated by the set's offset, the same for every
//                             receiver; points on empty texels count as zero): the thesis'
//                             weighting, which treats atlas points as uniform hemisphere
//                             directions (kept for comparison; it does not converge to the
//                             integral above).
// The final pass multiplies E_ind by rho/pi. Texels with a(y) > 0 are senders.
// A double-sided texel is two surfaces back to back (AtlasTextures.h): a sender sends each
// side's own radiance to that side, and p(y) counts both sides' power; a receiver adds what
// arrives against its normal to the back side's sum. With VISIBILITY_VOXEL each pair is
// weighted by the voxel occupancy's transmittance (common/voxel_visibility.glsl); with
// VISIBILITY_BVH a ray through the scene's triangles decides it (common/bvh.glsl), each end
// pushed half a texel edge off its surface and the first texel edge at each end not tested,
// as the voxel march pushes the ends one voxel and lets their voxels pass.
// Output: the sums of both sides (before the 1/N normalisation) added to the running sums by
// blending.
#include "atlas_common.glsl"
#include "sender_weight.glsl"
#include "near_field.glsl"
#include "../common/constants.glsl"
#include "../common/cosine_direction.glsl"
#include "../common/hash.glsl"
#ifdef VISIBILITY_VOXEL
#include "../common/voxel_visibility.glsl"
#endif

// The edge of the patch of area a that a texel stands for.
float texelEdge(float a) { return sqrt(max(a, 0.0)); }

#ifdef VISIBILITY_BVH
// 1 where nothing lies between the two texels, each seen from the side given. Each end starts
// half a texel edge off its surface, and the ray ignores what lies within one texel edge of
// either end: a texel's centre can lie up to half a texel past its triangle's edge (the
// gutter), where a ray from it would start behind the wall meeting it at a corner and every
// corner texel would be dark (the two rooms: relative RMSE 0.055 instead of 0.040).
float rayVisibility(vec3 x, vec3 xSide, float xArea, vec3 y, vec3 ySide, float yArea) {
    float edgeX = texelEdge(xArea), edgeY = texelEdge(yArea);
    vec3 a = x + xSide * (0.5 * edgeX);
    vec3 d = y + ySide * (0.5 * edgeY) - a;
    float len = length(d);
    if (len <= edgeX + edgeY) return 1.0;
    vec3 dir = d / len;
    return bvhOccluded(a + dir * edgeX, dir, (len - edgeX - edgeY) * (1.0 - 1e-4)) ? 0.0 : 1.0;
}
#endif

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_DIRECT_BACK) uniform sampler2D atlasDirectBack;
layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;
layout(binding = BIND_TEX_ATLAS_SAMPLES) uniform sampler2D atlasSamples;

layout(std430, binding = BIND_SSBO_ATLAS_SENDER_ROWS) readonly buffer SenderRows {
    vec2 rowPower[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SENDER_POOL) readonly buffer SenderPool {
    uint pool[];
};


// The samples [x, y) of the set and the sky directions [z, w) this draw adds: a set's loops
// are split over draws that each stay within SHADER_LOOP_ITERATIONS (AtlasGatherPass).
layout(location = LOC_ATLAS_GATHER_RANGE) uniform ivec4 gatherRange;

// This draw's share of the sky's irradiance on the side facing n (atlas.sky: its radiance and
// how many directions): cosine-distributed directions, stratified in their polar coordinate
// and new for each receiver and set, each seeing the sky unless the voxel occupancy blocks it
// on its way out of the cascade, or a triangle its ray meets (without visibility nothing
// blocks it). The draws' shares
// add up to the sky's irradiance.
vec3 skyIrradiance(vec3 x, vec3 n, float area, uint seed) {
    int directions = int(atlas.sky.w);
    if (directions <= 0 || gatherRange.z >= gatherRange.w) return vec3(0.0);
    float visible = 0.0;
    for (int i = gatherRange.z; i < gatherRange.w; ++i) {
        vec3 w = stratifiedCosineDirection(n, i, directions, seed);
#ifdef VISIBILITY_VOXEL
        int coarsest = voxelLevels() - 1;
        float toBoundary = exitDistance(x, w, levelOrigin(coarsest),
                levelVoxelSize(coarsest) * float(voxelResolution()));
        visible += toBoundary > 0.0 ? voxelTransmittance(x, n, x + w * toBoundary, -w) : 1.0;
#elif defined(VISIBILITY_BVH)
        float edge = texelEdge(area);
        visible += bvhOccluded(x + n * (0.5 * edge) + w * edge, w, 1e30) ? 0.0 : 1.0;
#else
        visible += 1.0;
#endif
    }
    return PI * atlas.sky.rgb * (visible / float(directions));
}

layout(location = 0) out vec4 outSum;
layout(location = 1) out vec4 outSumBack;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    if (texelFetch(atlasDirect, texel, 0).a <= 0.0) discard;
    vec4 receiverPosition = texelFetch(atlasPosition, texel, 0);
    vec3 x = receiverPosition.xyz;
    vec4 receiverNormal = texelFetch(atlasNormal, texel, 0);
    vec3 nx = receiverNormal.xyz;
    bool receiverTwoSided = receiverNormal.w > 0.5;
    int resolution = atlas.size.x;
    int count = atlas.size.y;
    bool area = atlas.size.z == ATLAS_ESTIMATOR_AREA;
    // The receiver's pick among each stratum's points changes with the set (sampling.y differs
    // between rotated sets), so its own estimate converges as sets accumulate.
    uint receiver = hash(uint(texel.y * resolution + texel.x) ^ floatBitsToUint(atlas.sampling.y));
    vec3 sum = vec3(0.0), sumBack = vec3(0.0);
    float floorPerPower = area ? importanceFloor(rowPower[resolution - 1]) : 0.0;
    float nearReach2 = nearFieldReach2();
    for (int i = gatherRange.x; i < gatherRange.y; ++i) {
        ivec2 t;
        if (area) {
            uint k = hash(receiver + uint(i)) % uint(ATLAS_POOL_STRIDE);
            uint sender = pool[uint(i) * uint(ATLAS_POOL_STRIDE) + k];
            if (sender == ~0u) continue;
            t = ivec2(int(sender % uint(resolution)), int(sender / uint(resolution)));
        } else {
            vec2 u = fract(texelFetch(atlasSamples, ivec2(i, 0), 0).xy + atlas.sampling.xy);
            t = min(ivec2(u * float(resolution)), ivec2(resolution - 1));
        }
        vec4 y = texelFetch(atlasPosition, t, 0);
        if (y.w <= 0.0) continue;
        vec3 d = y.xyz - x;
        float r2 = dot(d, d);
        if (r2 <= 0.0 || (area && r2 < nearReach2)) continue;
        vec3 w = d * inversesqrt(r2);
        vec4 senderNormal = texelFetch(atlasNormal, t, 0);
        bool senderTwoSided = senderNormal.w > 0.5;
        float cosX = dot(nx, w);
        float cosY = -dot(senderNormal.xyz, w);
        bool receiverBack = receiverTwoSided && cosX < 0.0;
        bool senderBack = senderTwoSided && cosY < 0.0;
        if (receiverBack) cosX = -cosX;
        if (senderBack) cosY = -cosY;
        if (cosX <= 0.0 || cosY <= 0.0) continue;
        vec3 front = texelFetch(atlasDirect, t, 0).rgb;
        vec3 back = senderTwoSided ? texelFetch(atlasDirectBack, t, 0).rgb : vec3(0.0);
        vec3 radiance = senderBack ? back : front;
        vec3 contribution;
        if (area) {
            // Drawn with probability a(y) w(y) / W (sender_weight.glsl; without atlas.importance
            // w = mean(L) of both sides and W = P): the weight is L / w times the geometry
            // term, and W multiplies the sums below.
            float power = combinedWeight(
                    senderWeightsPerArea(front, back, senderImportance(t)), floorPerPower);
            if (!(power > 0.0) || isinf(power)) continue;
            contribution = radiance / power * (cosX * cosY / max(r2, atlas.sampling.z));
        } else {
            contribution = radiance * cosX;
        }
#if defined(VISIBILITY_VOXEL) || defined(VISIBILITY_BVH)
        vec3 receiverSide = receiverBack ? -nx : nx;
        vec3 senderSide = senderBack ? -senderNormal.xyz : senderNormal.xyz;
#endif
#ifdef VISIBILITY_VOXEL
        contribution *= voxelTransmittance(x, receiverSide, y.xyz, senderSide);
#elif defined(VISIBILITY_BVH)
        contribution *= rayVisibility(x, receiverSide, receiverPosition.w, y.xyz, senderSide, y.w);
#endif
        if (receiverBack) sumBack += contribution;
        else sum += contribution;
    }
    float scale = area ? combinedWeight(rowPower[resolution - 1], floorPerPower)
                       : atlas.sampling.z;
    // The sums are divided by the samples accumulated: the sky's mean counts `count` times.
    vec3 sky = skyIrradiance(x, nx, receiverPosition.w, receiver * 7919u) * float(count);
    vec3 skyBack = receiverTwoSided
            ? skyIrradiance(x, -nx, receiverPosition.w, receiver * 7919u + 1u) * float(count)
            : vec3(0.0);
    // The near field (near_field.glsl), counted like the sky.
    if (area) {
        sky += nearFieldIrradiance(x, nx, receiverPosition.w, receiver * 7919u + 2u, atlasDirect,
                       atlasDirectBack, atlasNormal) * float(count);
        if (receiverTwoSided) {
            skyBack += nearFieldIrradiance(x, -nx, receiverPosition.w, receiver * 7919u + 3u,
                               atlasDirect, atlasDirectBack, atlasNormal) * float(count);
        }
    }
    outSum = vec4(sum * scale + sky, 1.0);
    outSumBack = vec4(sumBack * scale + skyBack, 1.0);
}
