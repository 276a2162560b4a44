// Builds cascade level `levelWritten` of the directional voxels (voxel_directional.glsl).
//
// Where the level was voxelized itself (all of level 0, the outer shell of coarser levels),
// voxelization and injection accumulated per face f the area of the surfaces f sees (A_f,
// projected onto f) and their flux (F_f). A face shows the surfaces facing it:
//   a_f = min(A_f, 1), reflected light rho F_f / A_f,
// so a wall whose two sides share a voxel shows each side only its own light (an isotropic
// voxel shows both sides the mean of the two), and a face no surface faces is empty. a_f is
// how much of the face the surfaces facing it cover: it weighs the faces' light against each
// other and tells cone tracing whether anything in the voxel faces the cone (a cone's
// opacity stays the isotropic coverage: a wall crossed obliquely must stay opaque, which
// projected areas, as small as the cosine, do not give). rgb is premultiplied as everywhere:
// rho F_f / max(A_f, 1) (a voxel the surfaces only graze stays dim, as inject_finalize.comp
// does isotropically); rho is the voxel's mean albedo. With voxel.inject_fragment_mean there
// is no flux: each face gets the isotropic value.
//
// Where the level was propagated from the finer one (its centre), each face composites the
// 8 finer voxels' same face front to back. One dispatch per level, finest first; v^3
// invocations.
#include "../common/constants.glsl"
#include "../common/voxel_cascade.glsl"
#include "voxel_directional.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) readonly uniform image3D voxelAlbedo;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) readonly uniform image3D voxelIrradiance;
layout(binding = BIND_IMG_VOXEL_DIRECTIONAL, rgba16f) uniform image3D voxelDirectional;
layout(location = LOC_VOXEL_LEVEL) uniform int levelWritten;

void main() {
    int v = voxelResolution();
    int level = levelWritten;
    ivec3 local = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(local, ivec3(v)))) return;
    ivec3 texel = local + ivec3(0, 0, level * v);
    bool propagated = level > 0 && all(greaterThanEqual(local, ivec3(v / 4))) &&
            all(lessThan(local, ivec3(3 * v / 4)));
    if (!propagated) {
        vec4 albedo = imageLoad(voxelAlbedo, texel);
        float coverage = clamp(albedo.a, 0.0, 1.0);
        if (int(voxel.modes.x) == INJECT_FRAGMENT) {
            vec4 value = vec4(0.0);
            if (coverage > 0.0) {
                // albedo and E are both premultiplied by coverage: the product carries it twice.
                vec3 reflected = albedo.rgb * imageLoad(voxelIrradiance, texel).rgb / coverage;
                value = min(vec4(reflected, coverage), vec4(HALF_STORE_MAX));
            }
            for (int face = 0; face < VOXEL_FACES; ++face) {
                imageStore(voxelDirectional, directionalTexel(texel, face), value);
            }
            return;
        }
        vec4 sums[VOXEL_FACES];
        for (int face = 0; face < VOXEL_FACES; ++face) {
            sums[face] = imageLoad(voxelDirectional, directionalTexel(texel, face));
        }
        vec3 albedoMean = coverage > 0.0 ? albedo.rgb / coverage : vec3(0.0);
        for (int face = 0; face < VOXEL_FACES; ++face) {
            // Light arriving at a side no surface faces lit a surface seen from behind (a
            // double-sided one, or a normal against the winding): its area is the other side's.
            float area = sums[face].a > 0.0 || max(sums[face].r, max(sums[face].g, sums[face].b)) <= 0.0
                    ? sums[face].a : sums[face ^ 1].a;
            vec4 value = area > 0.0
                    ? vec4(albedoMean * sums[face].rgb / max(area, 1.0), min(area, 1.0))
                    : vec4(0.0);
            imageStore(voxelDirectional, directionalTexel(texel, face),
                    min(value, vec4(HALF_STORE_MAX)));
        }
        return;
    }
    ivec3 fineBase = (local - v / 4) * 2 + ivec3(0, 0, (level - 1) * v);
    for (int face = 0; face < VOXEL_FACES; ++face) {
        vec4 children[8];
        for (int i = 0; i < 8; ++i) {
            ivec3 fine = fineBase + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
            children[i] = imageLoad(voxelDirectional, directionalTexel(fine, face));
        }
        imageStore(voxelDirectional, directionalTexel(texel, face),
                min(compositeBlock(children, face), vec4(HALF_STORE_MAX)));
    }
}
