// Voxelization, geometry stage (thesis Listing 4.1): project each triangle orthographically
// along the world axis its face normal is most aligned with, so it covers the most raster
// samples. The raster is v x voxel.multiplier samples across one projection over the coarsest
// level (the thesis' single volume), or, with voxel.raster_per_level, over each level the
// triangle reaches, so that every level's voxels get voxel.multiplier^2 samples per face
// whatever their size. One projection over the coarsest level gives the finest of L levels
// 2^(L-1) / voxel.multiplier raster pixels per voxel edge; under one, thin geometry leaves
// holes there. With per-level rasters the fragment stage keeps what falls in the level's own
// region, not in a finer one.
#include "../common/vertex_data.glsl"
#include "../common/voxel_cascade.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3 * VOXEL_MAX_LEVELS) out;

in VertexData { VERTEX_DATA_MEMBERS } vin[];

out VertexData { VERTEX_DATA_MEMBERS } vout;

// |cos| between the face normal and the projection axis: a raster pixel covers
// pixelArea / projectedCosine of the surface.
flat out float projectedCosine;
// The cascade level this copy of the triangle is rasterized for; -1 for the one raster over
// the coarsest level, whose fragments go to the finest level holding them.
flat out int rasterLevel;

bool boxesOverlap(vec3 loA, vec3 hiA, vec3 loB, vec3 hiB) {
    return all(lessThanEqual(loA, hiB)) && all(lessThanEqual(loB, hiA));
}

bool boxInside(vec3 lo, vec3 hi, vec3 outerLo, vec3 outerHi) {
    return all(greaterThanEqual(lo, outerLo)) && all(lessThan(hi, outerHi));
}

void main() {
    vec3 faceNormal = abs(cross(vin[1].position - vin[0].position, vin[2].position - vin[0].position));
    float cosine = max(faceNormal.x, max(faceNormal.y, faceNormal.z)) / max(length(faceNormal), 1e-30);
    vec3 lo = min(vin[0].position, min(vin[1].position, vin[2].position));
    vec3 hi = max(vin[0].position, max(vin[1].position, vin[2].position));
    bool perLevel = voxel.raster.x != 0.0;
    int first = perLevel ? 0 : voxelLevels() - 1;
    for (int level = first; level < voxelLevels(); ++level) {
        vec3 origin = levelOrigin(level);
        float extent = levelExtent(level);
        if (perLevel && !boxesOverlap(lo, hi, origin, origin + extent)) continue;
        // A triangle inside a finer level belongs to that level alone.
        if (perLevel && level > 0 && boxInside(lo, hi, levelOrigin(level - 1),
                levelOrigin(level - 1) + levelExtent(level - 1))) break;
        vec3 center = origin + 0.5 * extent;
        for (int i = 0; i < 3; ++i) {
            vec3 p = (vin[i].position - center) / (0.5 * extent);   // level -> [-1, 1]^3
            vec3 projected = faceNormal.x >= faceNormal.y && faceNormal.x >= faceNormal.z ? p.yzx
                           : faceNormal.y >= faceNormal.z ? p.zxy : p.xyz;
            gl_Position = vec4(projected.xy, projected.z * 0.5, 1.0);
            COPY_VERTEX_DATA(vout, vin[i])
            projectedCosine = cosine;
            rasterLevel = perLevel ? level : -1;
            EmitVertex();
        }
        EndPrimitive();
    }
}
