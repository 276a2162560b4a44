// Light injection, fragment stage (thesis 4.3.3.2, Alg. 3): every surface fragment the light
// sees computes its Lambert irradiance E from this light (DESIGN.md conventions; with the glTF
// model scaled so the voxel's albedo reflects what the surface's BRDF does of this light,
// voxel_reflectance.glsl) and adds it to the finest voxel containing it, under the voxel's
// spinlock. The early depth test against
// the depth pre-pass keeps fragments the light does not see from writing anything.
//
// INJECT_FRAGMENT (the thesis): the voxel keeps the mean E over this light's fragments.
// Fragments are spread evenly in the light's image, not over the surface, so that mean
// over-weights surfaces close to the light (a ceiling 1 cm above a point light reads its
// peak irradiance) and voxels the light sees only partly read the lit part's irradiance.
// INJECT_AREA: each fragment carries the flux through its light pixel, phi = E * A (A the
// surface area the pixel covers, light_view.glsl), and the voxel's irradiance is the summed
// flux over the surface area voxelization measured: the area-weighted mean irradiance of the
// surfaces in the voxel, lit or not. The sum is in fixed point (voxel_flux_sum.glsl), the
// same whatever order fragments arrive in. With voxel.anisotropic the flux is also summed per
// face of the voxel, projected onto the faces the lit side faces (directional_build.comp),
// under the voxel's lock.
#include "../common/voxel_cascade.glsl"

layout(early_fragment_tests) in;

#include "../common/light_view.glsl"
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#define VOXEL_DIRECTIONAL_SUMS
#include "voxel_directional.glsl"
#define VOXEL_FLUX_SUM_ADD
#include "voxel_flux_sum.glsl"
#include "voxel_lock.glsl"
#include "voxel_reflectance.glsl"

layout(location = LOC_INJECT_AXIS) uniform vec4 viewAxis;   // w = 1: orthographic
layout(location = LOC_INJECT_FOOTPRINT) uniform float pixelFootprint;
layout(location = LOC_INJECT_LIGHT) uniform int lightIndex;

layout(binding = BIND_IMG_VOXEL_HELPER, rgba16f) coherent uniform image3D voxelHelper;

in VertexData { VERTEX_DATA_MEMBERS } vin;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    // The side of the surface the light sees is the lit side, whatever the winding.
    LitSurface lit = litSurface(lights[lightIndex], vin.position, normalize(vin.normal));
    vec3 n = lit.normal;
    vec3 e = lit.irradiance * injectedIrradianceScale(m,
            materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color).rgb,
            dot(n, lit.toLight));
    if (max(e.r, max(e.g, e.b)) <= voxel.injection.x) discard;
    int level = finestLevel(vin.position);
    if (level < 0) discard;
    ivec3 texel = voxelTexel(vin.position, level);
    if (int(voxel.modes.x) == INJECT_FRAGMENT) {
        VOXEL_LOCKED_AVERAGE(texel, {
            vec4 previous = imageLoad(voxelHelper, texel);
            imageStore(voxelHelper, texel, roundToHalf(keep * previous + add * vec4(e, 1.0), dither));
        })
        return;
    }
    float area = lightPixelArea(viewAxis, pixelFootprint, lit, max(dot(n, lit.toLight), 0.05));
    float size = levelVoxelSize(level);
    vec3 flux = e * area / (size * size);
    addToFluxSum(texel, flux);
    if (anisotropicKind()) {
        VOXEL_LOCKED_AVERAGE(texel, { addToFacingFaces(texel, n, vec4(flux, 0.0), dither); })
    }
}
