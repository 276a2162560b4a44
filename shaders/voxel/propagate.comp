// Fills the centre of cascade level L from level L-1, which covers exactly that centre at
// twice the resolution (thesis 4.3.3.3, Listings 4.3/4.4): each invocation averages the
// 2x2x2 finer voxels. Albedo, coverage and irradiance are averaged over all 8 (albedo and
// irradiance are premultiplied by coverage, so an opaque black voxel stays distinct from an
// empty one and the averages stay premultiplied), normals weighted by coverage, and the
// surface's offset along the new normal (normal.w) from the children's surface points. One
// dispatch per level, 8^3 work groups, (v/2)^3 invocations.
//
// With voxel.coverage_max_axis (modes.z = 1) the coarse coverage is instead the opacity a
// ray meets along the most opaque axis: per axis, the mean over the 4 columns of
// 1 - (1 - a)(1 - b) for the column's two voxels, maximised over the axes. A wall filling one
// of the two layers then stays opaque at every level instead of halving its coverage per
// level (which lets cones see through walls and dims what they do see); albedo and
// irradiance are rescaled by the same factor so both stay per covered area unchanged.
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) uniform image3D voxelAlbedo;
layout(binding = BIND_IMG_VOXEL_NORMAL, rgba8_snorm) uniform image3D voxelNormal;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) uniform image3D voxelIrradiance;
layout(location = LOC_VOXEL_LEVEL) uniform int levelWritten;   // >= 1

void main() {
    int v = voxelResolution();
    int level = levelWritten;
    ivec3 coarse = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(coarse, ivec3(v / 2)))) return;
    ivec3 fineBase = coarse * 2 + ivec3(0, 0, (level - 1) * v);
    vec4 albedo = vec4(0.0), irradiance = vec4(0.0);
    vec3 normal = vec3(0.0);
    float coverage[8];
    vec4 plane[8];
    for (int i = 0; i < 8; ++i) {
        ivec3 fine = fineBase + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        vec4 a = imageLoad(voxelAlbedo, fine);
        coverage[i] = clamp(a.a, 0.0, 1.0);
        albedo += a;
        irradiance += imageLoad(voxelIrradiance, fine);
        plane[i] = imageLoad(voxelNormal, fine);
        normal += plane[i].xyz * a.a;
    }
    albedo /= 8.0;
    irradiance /= 8.0;
    if (voxel.modes.z != 0.0 && albedo.a > 0.0) {
        float axisOpacity = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            int step = 1 << axis;   // index offset of the column's second voxel
            float sum = 0.0;
            for (int i = 0; i < 8; ++i) {
                if ((i & step) != 0) continue;
                sum += 1.0 - (1.0 - coverage[i]) * (1.0 - coverage[i + step]);
            }
            axisOpacity = max(axisOpacity, sum / 4.0);
        }
        irradiance.rgb *= axisOpacity / albedo.a;
        albedo *= axisOpacity / albedo.a;
    }
    float len = length(normal);
    normal = len > 1e-4 ? normal / len : vec3(0.0);
    // The surface's distance from this voxel's centre along its normal: the mean over the
    // children of their surface point (child centre + its offset along its own normal),
    // weighted by coverage, in this voxel's sizes (a child is half of one).
    float offset = 0.0, weight = 0.0;
    for (int i = 0; i < 8; ++i) {
        float childLength = length(plane[i].xyz);
        if (coverage[i] <= 0.0 || childLength < 1e-4) continue;
        vec3 childCentre = vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) - 0.5;
        vec3 surface = childCentre + plane[i].w * plane[i].xyz / childLength;
        offset += coverage[i] * 0.5 * dot(surface, normal);
        weight += coverage[i];
    }
    offset = weight > 0.0 ? clamp(offset / weight, -1.0, 1.0) : 0.0;
    ivec3 target = coarse + ivec3(v / 4, v / 4, v / 4 + level * v);
    imageStore(voxelAlbedo, target, albedo);
    imageStore(voxelIrradiance, target, irradiance);
    imageStore(voxelNormal, target,
            albedo.a > 0.0 ? voxelNormalTexel(vec4(normal, offset)) : vec4(0.0));
}
