// Edge-aware smoothing of the traced indirect irradiance (the thesis' future work: "filtering
// and smart interpolation of the indirect result"): each texel becomes the mean of its
// (2r+1)^2 neighbourhood, every neighbour weighted by how close its view depth is to the
// centre's, so light does not cross depth edges. With the cone ring's jitter, the
// neighbourhood holds a whole period of its turns (gi/voxel/RingDither.h: 4 or 16 different
// rings): the mean behaves like many more cones.
#include "../common/voxel_cascade.glsl"

layout(local_size_x = VOXEL_FILTER_LOCAL_SIZE, local_size_y = VOXEL_FILTER_LOCAL_SIZE) in;

layout(binding = BIND_TEX_FILTER_SOURCE) uniform sampler2D source;
layout(binding = BIND_IMG_FILTER_TARGET, rgba16f) writeonly uniform image2D target;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(source, 0);
    if (any(greaterThanEqual(texel, size))) return;
    vec4 centre = texelFetch(source, texel, 0);
    if (centre.a <= 0.0) {
        imageStore(target, texel, centre);
        return;
    }
    int radius = int(voxel.smoothing.x);
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int y = -radius; y <= radius; ++y) {
        for (int x = -radius; x <= radius; ++x) {
            ivec2 p = texel + ivec2(x, y);
            if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) continue;
            vec4 t = texelFetch(source, p, 0);
            if (t.a <= 0.0) continue;
            float relative = abs(t.a - centre.a) / centre.a;
            float w = exp(-relative * relative * 2000.0);
            sum += w * t.rgb;
            weightSum += w;
        }
    }
    imageStore(target, texel, vec4(sum / weightSum, centre.a));
}
