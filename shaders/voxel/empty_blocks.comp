// The empty blocks of the coarsest cascade level (EmptyBlocksPass.h): one invocation per block
// of VOXEL_BLOCK^3 voxels; if none of them is occupied, each of their normal texels becomes
// kEmptyBlockTexel.
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_NORMAL, rgba8_snorm) uniform image3D voxelNormal;

void main() {
    ivec3 block = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(block, ivec3(voxelResolution() / VOXEL_BLOCK)))) return;
    ivec3 first = block * VOXEL_BLOCK + ivec3(0, 0, (voxelLevels() - 1) * voxelResolution());
    const int kVoxels = VOXEL_BLOCK * VOXEL_BLOCK * VOXEL_BLOCK;
    for (int i = 0; i < kVoxels; ++i) {
        ivec3 voxel = first + ivec3(i % VOXEL_BLOCK, (i / VOXEL_BLOCK) % VOXEL_BLOCK,
                i / (VOXEL_BLOCK * VOXEL_BLOCK));
        if (voxelOccupied(imageLoad(voxelNormal, voxel))) return;
    }
    for (int i = 0; i < kVoxels; ++i) {
        ivec3 voxel = first + ivec3(i % VOXEL_BLOCK, (i / VOXEL_BLOCK) % VOXEL_BLOCK,
                i / (VOXEL_BLOCK * VOXEL_BLOCK));
        imageStore(voxelNormal, voxel, kEmptyBlockTexel);
    }
}
