// Pyramid of reflected light above the coarsest cascade level (RadiancePyramidPass.h): mip 0
// averages 2x2x2 coarsest voxels, mip m > 0 averages 2x2x2 texels of mip m-1. Stored per
// texel: rgb = rho E x coverage, a = coverage, both averaged over all 8 children (empty ones
// count as zero), so rgb / a is the mean reflected light of the surfaces in the texel,
// weighted by how much of it they cover.
#include "../common/constants.glsl"
#include "../common/voxel_cascade.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) readonly uniform image3D voxelAlbedo;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) readonly uniform image3D voxelIrradiance;
layout(binding = BIND_IMG_VOXEL_PYRAMID_SOURCE, rgba16f) readonly uniform image3D pyramidSource;
layout(binding = BIND_IMG_VOXEL_PYRAMID, rgba16f) writeonly uniform image3D pyramidTarget;
layout(location = LOC_VOXEL_LEVEL) uniform int mipWritten;

void main() {
    int mip = mipWritten;
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, imageSize(pyramidTarget)))) return;
    int v = voxelResolution();
    ivec3 slab = ivec3(0, 0, (voxelLevels() - 1) * v);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        ivec3 child = texel * 2 + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        if (mip > 0) {
            sum += imageLoad(pyramidSource, child);
            continue;
        }
        vec4 albedo = imageLoad(voxelAlbedo, child + slab);
        float coverage = clamp(albedo.a, 0.0, 1.0);
        if (coverage <= 0.0) continue;
        // albedo and E are both premultiplied by coverage: their product carries it twice.
        vec3 reflected = albedo.rgb * imageLoad(voxelIrradiance, child + slab).rgb / coverage;
        sum += vec4(reflected, coverage);
    }
    imageStore(pyramidTarget, texel, min(sum / 8.0, vec4(HALF_STORE_MAX)));
}
