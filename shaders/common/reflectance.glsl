// What a surface sends on of the light it receives, as the diffuse light every GI mode
// carries from one surface to the next (voxels, atlas texels, VPLs). Lambertian materials
// reflect their base colour. With the glTF model a surface's lobes send on its directional
// albedo for the direction the light comes from (brdf.glsl), as the path tracer's surfaces
// reflect it: a metal nearly all of it, a dielectric less than its base colour, the more so
// the more grazing the light. Light from every direction alike (the indirect light of further
// bounces) is reflected with the white-sky albedo.
#ifndef GI_REFLECTANCE_GLSL
#define GI_REFLECTANCE_GLSL

#include "brdf.glsl"
#include "material.glsl"

// Of light arriving at cosine cosL to the lit side's normal.
vec3 reflectanceOfLight(GpuMaterial m, vec3 baseColor, float cosL, bool gltf) {
    if (!gltf) return baseColor;
    return directionalAlbedo(gltfSurface(baseColor, m.metallicRoughness.x, m.metallicRoughness.y),
            cosL);
}

// Of light arriving from every direction alike.
vec3 reflectanceOfUniformLight(GpuMaterial m, vec3 baseColor, bool gltf) {
    if (!gltf) return baseColor;
    return uniformLightAlbedo(gltfSurface(baseColor, m.metallicRoughness.x, m.metallicRoughness.y));
}

#endif
