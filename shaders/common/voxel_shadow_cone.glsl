// shadow.method=voxel: the light's visibility from one cone through a voxel occupancy of the
// scene (the cascade layout of voxel_cascade.glsl, coverage in the alpha of the texture at
// BIND_TEX_VOXEL_ALBEDO), as voxel GI demos shadow their lights. The cone's aperture is the
// light's: an area light's bounding sphere as seen from the point, a punctual light's none,
// so its cone stays one finest voxel wide. Samples half a cone diameter apart read the level
// whose voxels are as wide as the cone (trilinear, blended between the two nearest levels)
// and composite front to back; each sample's coverage is corrected for the step, so the
// opacity does not depend on how often a voxel is sampled. The result is smooth but blurred
// by the voxel size: thin occluders leak and contact shadows are lost within about two
// finest voxels of the surface, where the cone has to start to leave its own voxel.
#ifndef GI_VOXEL_SHADOW_CONE_GLSL
#define GI_VOXEL_SHADOW_CONE_GLSL

#include "voxel_cascade.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D shadowOccupancy;

const int kMaxShadowConeSteps = 512;

// Coverage of the cone's footprint at p: `lod` in finest voxels, log2.
float coneCoverage(vec3 p, float lod) {
    int levels = voxelLevels();
    float clamped = clamp(lod, 0.0, float(levels - 1));
    int lower = int(floor(clamped));
    int upper = min(lower + 1, levels - 1);
    // A point beyond a level's region reads the next level that holds it.
    while (lower < levels && !insideLevel(p, lower)) ++lower;
    if (lower >= levels) return 0.0;
    upper = max(upper, lower);
    while (upper < levels && !insideLevel(p, upper)) ++upper;
    float a = textureLod(shadowOccupancy, voxelTexcoord(p, lower), 0.0).a;
    if (upper >= levels || upper == lower) return a;
    float b = textureLod(shadowOccupancy, voxelTexcoord(p, upper), 0.0).a;
    return mix(a, b, clamp(clamped - float(lower), 0.0, 1.0));
}

// Share of the light that passes a cone from `position` (normal n) along `dir` to distance
// `tEnd` (m), widening by `tanHalfAngle`; 1 outside the occupancy.
float voxelConeVisibility(vec3 position, vec3 n, vec3 dir, float tEnd, float tanHalfAngle) {
    if (voxelLevels() <= 0) return 1.0;
    float finest = levelVoxelSize(0);
    // Off the surface by two voxels along the normal: a trilinear read one voxel off a wall
    // still holds half the wall's coverage, and a cone that runs along its own wall (a
    // vertical face lit from above) would keep adding it up.
    vec3 origin = position + n * (2.0 * finest);
    float t = finest;
    float occlusion = 0.0;
    for (int i = 0; i < kMaxShadowConeSteps && t < tEnd && occlusion < 0.99; ++i) {
        float diameter = max(finest, 2.0 * t * tanHalfAngle);
        vec3 p = origin + dir * t;
        if (finestLevel(p) < 0) break;
        float lod = log2(diameter / finest);
        float step = 0.5 * diameter;
        float coverage = clamp(coneCoverage(p, lod), 0.0, 1.0);
        // The coverage holds for one voxel of the level read; the step covers step/size of it.
        float levelSize = finest * exp2(clamp(lod, 0.0, float(voxelLevels() - 1)));
        float alpha = 1.0 - pow(1.0 - min(coverage, 0.999), step / levelSize);
        occlusion += (1.0 - occlusion) * alpha;
        t += step;
    }
    return 1.0 - occlusion;
}

#endif
