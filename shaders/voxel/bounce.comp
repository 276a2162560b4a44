// A further bounce of light in the voxels (gi.bounces > 1, BouncePass.h). Over every voxel a
// level was voxelized into itself (all of level 0, the outer shell of coarser levels; their
// centres are propagated again afterwards):
//   STEP_GATHER  every cone of voxel.cones from the voxel's surface over the hemisphere its
//                mean normal faces (cone_tracing.glsl, as the screen-space trace; no pixels
//                to share them with) give the indirect irradiance
//                G it receives from the voxels' present light, E_direct + the last bounce's
//                G. Written, premultiplied by coverage, to the helper (the cones read the
//                irradiance it will change).
//   STEP_APPLY   irradiance = E_direct + G: the gathered texture remembers the G already
//                added, so the difference is added. The voxel then sends rho/pi (E_direct +
//                G), the light that has bounced once more.
// The cones see a voxel only from the side its normal faces, so a voxel gathers on that side
// only (and one whose surfaces face both ways, mean normal near zero, gathers nothing).
#include "../common/hash.glsl"
#include "cone_tracing.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_HELPER, rgba16f) uniform image3D voxelHelper;
#ifdef STEP_APPLY
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) uniform image3D voxelIrradiance;
layout(binding = BIND_IMG_VOXEL_GATHERED, rgba16f) uniform image3D voxelGathered;
#endif

// Below this length the children's normals cancel: surfaces facing opposite ways.
const float kMinNormalLength = 0.25;

// Whether `texel` (slab included) holds what its level voxelized, not a propagated average.
bool voxelizedHere(ivec3 texel) {
    int v = voxelResolution();
    int level = texel.z / v;
    ivec3 local = texel - ivec3(0, 0, level * v);
    return level == 0 || any(lessThan(local, ivec3(v / 4))) ||
           any(greaterThanEqual(local, ivec3(3 * v / 4)));
}

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, imageSize(voxelHelper))) || !voxelizedHere(texel)) return;
    float coverage = clamp(texelFetch(voxelAlbedoTexture, texel, 0).a, 0.0, 1.0);
    if (coverage <= 0.0) return;
#ifdef STEP_GATHER
    vec4 plane = texelFetch(voxelNormalTexture, texel, 0);
    float normalLength = length(plane.xyz);
    if (normalLength < kMinNormalLength) return;
    vec3 n = plane.xyz / normalLength;
    int v = voxelResolution();
    int level = texel.z / v;
    float size = levelVoxelSize(level);
    vec3 centre = levelOrigin(level) + (vec3(texel - ivec3(0, 0, level * v)) + 0.5) * size;
    vec3 surface = centre + n * (plane.w * size);
    // Leave the surface's own voxel before the first sample, as the screen-space trace does;
    // the rings turn by a random part of their spacing per voxel, so neighbours sample
    // different directions.
    vec3 origin = surface + n * size;
    uint seed = hash(uint(texel.x) + uint(v) * (uint(texel.y) + uint(v) * uint(texel.z)));
    float turn = float(seed >> 8) / 16777216.0;
    vec3 gathered = coneIrradiance(origin, n, turn, 0.5, 0, 1, voxel.trace.y);
    imageStore(voxelHelper, texel, vec4(min(gathered * coverage, vec3(HALF_STORE_MAX)), 0.0));
#else
    vec4 gathered = imageLoad(voxelHelper, texel);
    vec4 previous = imageLoad(voxelGathered, texel);
    vec4 irradiance = imageLoad(voxelIrradiance, texel);
    irradiance.rgb = max(irradiance.rgb + gathered.rgb - previous.rgb, vec3(0.0));
    imageStore(voxelIrradiance, texel, min(irradiance, vec4(HALF_STORE_MAX)));
    imageStore(voxelGathered, texel, gathered);
    imageStore(voxelHelper, texel, vec4(0.0));
#endif
}
