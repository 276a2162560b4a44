// Voxelization, fragment stage: averages albedo (with coverage 1) and normal of every
// fragment into the finest level containing it, under the voxel's spinlock (thesis 4.3.3.1),
// and sums the surface area the fragments stand for (in units of the voxel's face area), so
// light injection can turn flux into the voxel's mean irradiance. The normal's w averages
// the surface's signed distance from the voxel centre along the normal (in voxel sizes), so
// a voxel of one flat surface knows where in it that surface lies. With voxel.anisotropic the
// area is also summed per face of the voxel, projected onto the faces the surface faces
// (directional_build.comp).
// With voxel.msaa the raster has several samples per pixel: a fragment runs wherever the
// surface covers one of them, stands for the area of those it covers, and is read (material,
// position) at their centroid, a point of the surface inside the pixel, so a sliver of a
// surface that passes between pixel centres is voxelized too, into the voxel it lies in.
// Without it gl_NumSamples is 1, the mask one bit and the centroid the pixel's centre.
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"
#define VOXEL_DIRECTIONAL_SUMS
#include "voxel_directional.glsl"
#include "voxel_lock.glsl"
#include "voxel_reflectance.glsl"

layout(binding = BIND_IMG_VOXEL_ALBEDO, rgba16f) coherent uniform image3D voxelAlbedo;
layout(binding = BIND_IMG_VOXEL_NORMAL, rgba8_snorm) coherent uniform image3D voxelNormal;
layout(binding = BIND_IMG_VOXEL_IRRADIANCE, rgba16f) coherent uniform image3D voxelIrradiance;

in VertexData { VERTEX_DATA_MEMBERS } vin;

flat in float projectedCosine;
flat in int rasterLevel;

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, interpolateAtCentroid(vin.texcoord0),
            interpolateAtCentroid(vin.texcoord1), interpolateAtCentroid(vin.color));
    if (materialCutOut(m, baseColor.a)) discard;
    vec3 reflectance = voxelReflectance(m, baseColor.rgb);
    vec3 position = interpolateAtCentroid(vin.position);
    // With a raster per level (voxelize.geom), a fragment in a finer level's region is that
    // level's.
    int level = finestLevel(position);
    if (level < 0 || (rasterLevel >= 0 && level != rasterLevel)) discard;
    ivec3 texel = voxelTexel(position, level);
    vec3 n = normalize(vin.normal);
    float size = levelVoxelSize(level);
    vec3 centre = levelOrigin(level) +
            (vec3(texel - ivec3(0, 0, level * voxelResolution())) + 0.5) * size;
    float planeOffset = clamp(dot(position - centre, n) / size, -1.0, 1.0);
    // A raster pixel is 1/multiplier of the rasterized level's voxel edge (the coarsest
    // level's with one raster); in this voxel's face areas:
    int rasterized = rasterLevel >= 0 ? rasterLevel : voxelLevels() - 1;
    float pixelEdge = levelVoxelSize(rasterized) / size;
    float covered = float(bitCount(gl_SampleMaskIn[0])) / float(gl_NumSamples);
    float area = voxel.raster.y * covered * pixelEdge * pixelEdge / max(projectedCosine, 0.577);
    VOXEL_LOCKED_AVERAGE(texel, {
        vec4 albedo = imageLoad(voxelAlbedo, texel);
        vec4 normal = imageLoad(voxelNormal, texel);
        imageStore(voxelAlbedo, texel, roundToHalf(keep * albedo + add * vec4(reflectance, 1.0), dither));
        imageStore(voxelNormal, texel,
                voxelNormalTexel(roundToSnorm8(keep * normal + add * vec4(n, planeOffset), dither)));
        vec4 irradiance = imageLoad(voxelIrradiance, texel);
        vec3 projected = voxel.raster.z != 0.0 ? area * abs(n) : vec3(0.0);
        imageStore(voxelIrradiance, texel,
                roundToHalf(irradiance + vec4(projected, area), dither));
        if (anisotropicKind()) addToFacingFaces(texel, n, vec4(0.0, 0.0, 0.0, area), dither);
    })
}
