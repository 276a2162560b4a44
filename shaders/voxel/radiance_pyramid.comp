// Pyramid of reflected light above the coarsest cascade level (RadiancePyramidPass.h) for
// isotropic voxels, kept per face as the directional pyramid is (x-slab f of every mip, the
// faces of voxel_directional.glsl): mip 0 averages 2x2x2 coarsest voxels, mip m > 0 averages
// 2x2x2 texels of mip m-1. Face f weighs each voxel by the area its surfaces show that face,
// coverage x faceProjection(n, f) with n the voxel's mean normal (shorter where its surfaces
// face apart: the two sides of a thin wall show no face): rgb = rho E x that area, a = the
// area, averaged over all 8 children (empty ones count as zero), so rgb / a is the mean
// reflected light of the surfaces in the texel that face that way. Only a level voxelized
// directly holds its surfaces' mean normal; a propagated coarsest level (a cascade of several
// levels) holds the normal of its children's mean, normalised (voxel_plane.glsl), which does
// not say which faces its surfaces show (on the thesis' fixed plan, the corner voxels' floor
// light went to the walls' faces: the Cornell box's colour bleeding fell by a third and its
// energy rose to 1.16). There every face gets the whole coverage, and each face holds the
// one average of every surface the texel holds.
#include "../common/constants.glsl"
#include "../common/voxel_cascade.glsl"
#include "voxel_directional.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) readonly uniform image3D voxelAlbedo;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) readonly uniform image3D voxelIrradiance;
layout(binding = BIND_IMG_VOXEL_NORMAL, rgba8_snorm) readonly uniform image3D voxelNormal;
layout(binding = BIND_IMG_VOXEL_PYRAMID_SOURCE, rgba16f) readonly uniform image3D pyramidSource;
layout(binding = BIND_IMG_VOXEL_PYRAMID, rgba16f) writeonly uniform image3D pyramidTarget;
layout(location = LOC_VOXEL_LEVEL) uniform int mipWritten;

void main() {
    int mip = mipWritten;
    int slab = imageSize(pyramidTarget).x / VOXEL_FACES;   // texels per face and side
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(slab)))) return;
    int v = voxelResolution();
    ivec3 cascadeSlab = ivec3(0, 0, (voxelLevels() - 1) * v);
    vec4 sums[VOXEL_FACES];
    for (int face = 0; face < VOXEL_FACES; ++face) sums[face] = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        ivec3 child = texel * 2 + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        if (mip > 0) {
            for (int face = 0; face < VOXEL_FACES; ++face) {
                sums[face] += imageLoad(pyramidSource, child + ivec3(face * 2 * slab, 0, 0));
            }
            continue;
        }
        vec4 albedo = imageLoad(voxelAlbedo, child + cascadeSlab);
        float coverage = clamp(albedo.a, 0.0, 1.0);
        if (coverage <= 0.0) continue;
        // albedo and E are both premultiplied by coverage: their product carries it twice.
        vec3 reflected = albedo.rgb * imageLoad(voxelIrradiance, child + cascadeSlab).rgb / coverage;
        vec3 n = imageLoad(voxelNormal, child + cascadeSlab).xyz;
        bool voxelizedHere = voxelLevels() == 1;
        for (int face = 0; face < VOXEL_FACES; ++face) {
            float shown = voxelizedHere ? faceProjection(n, face) : 1.0;
            sums[face] += shown * vec4(reflected, coverage);
        }
    }
    for (int face = 0; face < VOXEL_FACES; ++face) {
        imageStore(pyramidTarget, texel + ivec3(face * slab, 0, 0),
                min(sums[face] / 8.0, vec4(HALF_STORE_MAX)));
    }
}
