// Atlas gather (thesis 4.6, eq. 9), one fragment per atlas texel: the receiver x reads N
// sample texels y of the atlas at the Hammersley points (rotated by the set's offset), skips
// empty texels and pairs that do not face each other, and adds the sender's direct radiance
// L(y). Two estimators of E_ind(x) = integral of L(y) cos(theta_x) cos(theta_y) / r^2 dA(y):
//   ATLAS_ESTIMATOR_AREA      sum L(y) cos(theta_x) cos(theta_y) / max(r^2, a(y)) * a(y)
//                             * R^2 / N, with a(y) the surface area the sample texel stands
//                             for (the position layer's w). The N points are uniform over the
//                             R^2 texels, so each texel has probability 1/R^2 and stands for
//                             a(y) of the surface: R^2/N * sum f(y) a(y) estimates the area
//                             integral. Clamping r^2 at a(y) (one texel's area) bounds the
//                             1/r^2 singularity of texels next to the receiver.
//   ATLAS_ESTIMATOR_MERZ2010  sum L(y) cos(theta_x) * 2 pi / N: the thesis' weighting, which
//                             treats atlas points as uniform hemisphere directions (kept for
//                             comparison; it does not converge to the integral above).
// The final pass multiplies E_ind by rho/pi. Only texels whose centre lies on the surface
// (a(y) > 0) are senders; texels written by the conservative draw are receivers only.
// Double-sided senders send to both sides; a double-sided receiver keeps the mean of both
// sides' irradiance (the atlas has one value per surface point). With VISIBILITY_VOXEL each
// pair is weighted by the voxel occupancy's transmittance (voxel_visibility.glsl).
// Output: the sum (before the 1/N normalisation) added to the running sums by blending.
#include "atlas_common.glsl"
#ifdef VISIBILITY_VOXEL
#include "voxel_visibility.glsl"
#endif

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_NORMAL) uniform sampler2D atlasNormal;
layout(binding = BIND_TEX_ATLAS_POSITION) uniform sampler2D atlasPosition;
layout(binding = BIND_TEX_ATLAS_SAMPLES) uniform sampler2D atlasSamples;

layout(location = 0) out vec4 outSum;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    if (texelFetch(atlasDirect, texel, 0).a <= 0.0) discard;
    vec3 x = texelFetch(atlasPosition, texel, 0).xyz;
    vec4 receiverNormal = texelFetch(atlasNormal, texel, 0);
    vec3 nx = receiverNormal.xyz;
    bool receiverTwoSided = receiverNormal.w > 0.5;
    int resolution = atlas.size.x;
    int count = atlas.size.y;
    bool area = atlas.size.z == ATLAS_ESTIMATOR_AREA;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < count; ++i) {
        vec2 u = fract(texelFetch(atlasSamples, ivec2(i, 0), 0).xy + atlas.sampling.xy);
        ivec2 t = min(ivec2(u * float(resolution)), ivec2(resolution - 1));
        vec4 y = texelFetch(atlasPosition, t, 0);
        if (y.w <= 0.0) continue;
        vec3 d = y.xyz - x;
        float r2 = dot(d, d);
        if (r2 <= 0.0) continue;
        vec3 w = d * inversesqrt(r2);
        vec4 senderNormal = texelFetch(atlasNormal, t, 0);
        float cosX = dot(nx, w);
        float cosY = -dot(senderNormal.xyz, w);
        if (receiverTwoSided) cosX = 0.5 * abs(cosX);
        if (senderNormal.w > 0.5) cosY = abs(cosY);
        if (cosX <= 0.0 || cosY <= 0.0) continue;
        vec3 radiance = texelFetch(atlasDirect, t, 0).rgb;
#ifdef VISIBILITY_VOXEL
        vec3 receiverSide = receiverTwoSided && dot(nx, w) < 0.0 ? -nx : nx;
        vec3 senderSide = dot(senderNormal.xyz, w) > 0.0 ? -senderNormal.xyz : senderNormal.xyz;
        radiance *= voxelTransmittance(x, receiverSide, y.xyz, senderSide);
#endif
        sum += area ? radiance * (cosX * cosY / max(r2, y.w) * y.w) : radiance * cosX;
    }
    outSum = vec4(sum * atlas.sampling.z, 1.0);
}
