// The empty voxels' distance to the nearest occupied voxel on the coarsest cascade level
// (EmptyDistancePass.h), one axis per dispatch, one invocation per voxel:
//   axis 0  the distance along x (0 = occupied), from the normal texels;
//   axis 1  the least max(|dy|, axis 0's distance) over the y-neighbours;
//   axis 2  the same over z: the Chebyshev distance, written into the empty voxels' texels.
// Every step looks kEmptyDistanceCap voxels to either side, so distances stop at one more.
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_NORMAL, rgba8_snorm) uniform image3D voxelNormal;
layout(binding = BIND_IMG_VOXEL_DISTANCE_X, r8ui) uniform uimage3D distanceX;
layout(binding = BIND_IMG_VOXEL_DISTANCE_XY, r8ui) uniform uimage3D distanceXY;
layout(location = LOC_VOXEL_LEVEL) uniform int axis;

void main() {
    int v = voxelResolution();
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, ivec3(v)))) return;
    ivec3 slab = ivec3(0, 0, (voxelLevels() - 1) * v);
    ivec3 along = ivec3(axis == 0, axis == 1, axis == 2);
    int least = kEmptyDistanceCap + 1;
    for (int k = -kEmptyDistanceCap; k <= kEmptyDistanceCap; ++k) {
        ivec3 other = voxel + k * along;
        if (any(lessThan(other, ivec3(0))) || any(greaterThanEqual(other, ivec3(v)))) continue;
        int d;
        if (axis == 0) {
            d = voxelOccupied(imageLoad(voxelNormal, other + slab)) ? 0 : kEmptyDistanceCap + 1;
        } else {
            d = int(axis == 1 ? imageLoad(distanceX, other).r : imageLoad(distanceXY, other).r);
        }
        least = min(least, max(abs(k), d));
    }
    if (axis == 0) {
        imageStore(distanceX, voxel, uvec4(least));
    } else if (axis == 1) {
        imageStore(distanceXY, voxel, uvec4(least));
    } else if (least > 0) {
        imageStore(voxelNormal, voxel + slab, voxelEmptyTexel(least));
    }
}
