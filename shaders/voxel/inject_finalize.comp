// Turns what injection accumulated into irradiance (thesis 4.3.3.2: the compute pass that
// makes the per-voxel average a sum over lights).
// INJECT_FRAGMENT, after each light: adds the light's mean irradiance to the sum over lights
// (the thesis keeps the mean over lights and multiplies by their count: the same sum).
// INJECT_AREA, once after all lights, over every occupied voxel: the voxel's coverage
// becomes its surface area in units of its face area (at most 1) and its irradiance the
// summed flux (voxel_flux_sum.glsl) over max(area, face area). A voxel a surface only grazes
// thus stays translucent and dim instead of turning into an opaque cube glowing with the flux
// of a whole light pixel. Albedo and irradiance are both stored premultiplied by coverage, as
// propagation and the filtered reads of cone tracing expect (an empty neighbour then
// lowers a trilinear read's coverage, not the albedo it returns).
// Both clear the helper.
#include "../common/constants.glsl"
#include "../common/voxel_cascade.glsl"
#include "voxel_flux_sum.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_IMG_VOXEL_HELPER, rgba16f) uniform image3D voxelHelper;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) uniform image3D voxelIrradiance;
layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) uniform image3D voxelAlbedo;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, imageSize(voxelHelper)))) return;
    vec4 helper = imageLoad(voxelHelper, texel);
    vec4 current = imageLoad(voxelIrradiance, texel);
    vec3 total;
    if (int(voxel.modes.x) == INJECT_AREA) {
        float area = current.a;
        if (area <= 0.0) return;
        vec4 albedo = imageLoad(voxelAlbedo, texel);
        float coverage = min(area, 1.0);
        imageStore(voxelAlbedo, texel, vec4(albedo.rgb * coverage, coverage));
        total = fluxSumAt(texel) / max(area, 1.0);
    } else {
        if (helper.a == 0.0) return;
        total = current.rgb + helper.rgb;
    }
    imageStore(voxelIrradiance, texel, vec4(min(total, vec3(HALF_STORE_MAX)), current.a));
    imageStore(voxelHelper, texel, vec4(0.0));
}
