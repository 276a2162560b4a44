// The pyramid above the coarsest level (RadiancePyramidPass.h) for anisotropic voxels: each
// texel is stored as seen from each face (x-slab f of every mip), the 2x2x2 texels below it
// composited front to back along the face's axis (voxel_directional.glsl). Mip 0 reads the
// coarsest level of the directional voxels, mip m > 0 mip m-1.
#include "../common/constants.glsl"
#include "../common/voxel_cascade.glsl"
#include "voxel_directional.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_DIRECTIONAL, rgba16f) readonly uniform image3D voxelDirectional;
layout(binding = BIND_IMG_VOXEL_PYRAMID_SOURCE, rgba16f) readonly uniform image3D pyramidSource;
layout(binding = BIND_IMG_VOXEL_PYRAMID, rgba16f) writeonly uniform image3D pyramidTarget;
layout(location = LOC_VOXEL_LEVEL) uniform int mipWritten;

void main() {
    int mip = mipWritten;
    ivec3 size = imageSize(pyramidTarget);
    int slab = size.x / VOXEL_FACES;   // texels per face and axis of this mip
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(slab)))) return;
    int v = voxelResolution();
    int sourceSlab = mip > 0 ? 2 * slab : v;
    ivec3 sourceOffset = mip > 0 ? ivec3(0) : ivec3(0, 0, (voxelLevels() - 1) * v);
    for (int face = 0; face < VOXEL_FACES; ++face) {
        vec4 children[8];
        for (int i = 0; i < 8; ++i) {
            ivec3 child = texel * 2 + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) + sourceOffset +
                    ivec3(face * sourceSlab, 0, 0);
            children[i] = mip > 0 ? imageLoad(pyramidSource, child)
                                  : imageLoad(voxelDirectional, child);
        }
        imageStore(pyramidTarget, texel + ivec3(face * slab, 0, 0),
                min(compositeBlock(children, face), vec4(HALF_STORE_MAX)));
    }
}
