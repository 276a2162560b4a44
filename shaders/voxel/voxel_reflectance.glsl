// What the surfaces in a voxel reflect of the light injected into them (reflectance.glsl;
// voxel.modes.y = 1 for the glTF model, shared.h). The voxel's albedo is the reflectance of
// light from every direction alike, what further bounces reflect, and each light's injected
// irradiance carries the ratio of its own reflectance to that one, so albedo x irradiance is
// what the surfaces reflect of that light.
#ifndef GI_VOXEL_REFLECTANCE_GLSL
#define GI_VOXEL_REFLECTANCE_GLSL

#include "../common/reflectance.glsl"
#include "../common/voxel_cascade.glsl"

bool voxelGltfReflectance() { return voxel.modes.y != 0.0; }

// The albedo a fragment adds to its voxel.
vec3 voxelReflectance(GpuMaterial m, vec3 baseColor) {
    return reflectanceOfUniformLight(m, baseColor, voxelGltfReflectance());
}

// What a light's irradiance at a fragment is multiplied by, the light arriving at cosine cosL
// to the lit side's normal.
vec3 injectedIrradianceScale(GpuMaterial m, vec3 baseColor, float cosL) {
    if (!voxelGltfReflectance()) return vec3(1.0);
    vec3 uniformLight = reflectanceOfUniformLight(m, baseColor, true);
    vec3 ratio = reflectanceOfLight(m, baseColor, cosL, true) / max(uniformLight, vec3(1e-6));
    return mix(vec3(0.0), ratio, greaterThan(uniformLight, vec3(0.0)));
}

#endif
