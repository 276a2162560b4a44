// The surface plane a voxel's normal texel describes (BIND_TEX_VOXEL_NORMAL), and whether a
// segment crosses it: a voxel of one flat surface stops what crosses that surface only.
//
// Level 0 (voxelize.frag): xyz = the mean of the fragments' unit normals, w = their mean
// signed distance from the voxel centre along their normal, in voxel sizes. One flat surface
// gives a mean normal of (nearly) unit length; several orientations shorten it.
// Coarser levels (propagate.comp): xyz = the coverage-weighted mean of the 8 children's
// normals, normalised; w = the mean of the children's surface points along it. The length is
// 1 whatever the children hold, so it no longer tells one plane from several, and where a
// floor meets a wall the mean plane runs diagonally between them: it is neither surface.
// Only level 0 can therefore say "one plane".
#ifndef GI_VOXEL_PLANE_GLSL
#define GI_VOXEL_PLANE_GLSL

// Mean normals at least this long come from one plane (two planes at right angles in equal
// parts give 0.71; the 8-bit normal's rounding moves the length by about 0.01).
const float kOnePlaneNormal = 0.9;

// A segment crosses a voxel's plane when it comes within this many voxel sizes of it (along
// the normal) on both sides: the stored offset is 8-bit and stochastically rounded, and a
// surface lying on a voxel face is stored as an offset of -0.5 or +0.5 that may round to just
// outside the voxel.
const float kPlaneTolerance = 0.1;

// Level-0 voxels whose mean normal is at least this long are met at their mean plane by the
// visibility marches (voxelMetAtPlane): one flat surface (length about 1), or surfaces meeting
// at an edge or a corner (two at right angles in equal parts: 0.71; three: 0.58), where the
// mean plane cuts the edge off between its faces. Shorter mean normals come from surfaces
// facing apart, such as both faces of a slab thinner than a voxel.
const float kMeanPlaneNormal = 0.5;

// Empty voxels' normal texels: all zero as cleared, and on the coarsest level of isotropic
// voxels a zero normal over minus the voxel's Chebyshev distance to the nearest occupied voxel
// in 127ths (EmptyDistancePass.h), at most kEmptyDistanceCap + 1.
const int kEmptyDistanceCap = 4;

vec4 voxelEmptyTexel(int distance) {
    return vec4(0.0, 0.0, 0.0, -float(distance) / 127.0);
}

// Whether a voxel is occupied, from its normal texel alone: voxelization and propagation
// never give an occupied voxel an empty texel (voxelNormalTexel). Cone tracing's walk thus
// fetches one texel a step, not the coverage and then the normal.
bool voxelOccupied(vec4 plane) {
    return plane.xyz != vec3(0.0) || plane.w > 0.0;
}

// An empty voxel's distance to the nearest occupied one, 0 where none was written.
int voxelEmptyDistance(vec4 plane) {
    return int(round(-plane.w * 127.0));
}

// The normal texel an occupied voxel stores: surfaces facing opposite ways can cancel its
// normal to nothing (their offsets to zero or less); the smallest positive 8-bit offset then
// marks it occupied (no reader uses the offset of a normal that short).
vec4 voxelNormalTexel(vec4 plane) {
    return voxelOccupied(plane) ? plane : vec4(0.0, 0.0, 0.0, 1.0 / 127.0);
}

// Whether the voxel's normal texel on `level` says it holds one plane. `coarserLevels` takes
// a coarser level's unit-length normal for one plane as well, which it is not where surfaces
// meet (above); only cone tracing's coarsest-level walk asks for that, under
// voxel.coarse_planes.
bool voxelHoldsOnePlane(vec4 plane, int level, bool coarserLevels) {
    return (level == 0 || coarserLevels) && length(plane.xyz) >= kOnePlaneNormal;
}

// Whether a visibility march meets the voxel only where the segment crosses its mean plane
// (else anywhere it crosses the voxel). A segment passing an edge voxel outside the edge, as
// rays from a wall past a block's edge do, then passes: blocking it by coverage made every
// block look a voxel larger, and VPL and converged atlas GI lost light beside every block and
// in every corner (accuracy-analysis.md). Coarser levels' planes are averages of their
// children (above), so their voxels block wherever crossed.
bool voxelMetAtPlane(vec4 plane, int level) {
    return level == 0 && length(plane.xyz) >= kMeanPlaneNormal;
}

// Signed distance of p from the plane of the voxel (centre, edge size), in voxel sizes,
// positive on the side the normal points to.
float voxelPlaneDistance(vec4 plane, vec3 centre, float size, vec3 p) {
    vec3 n = plane.xyz / length(plane.xyz);
    return dot(n, p - centre) / size - plane.w;
}

// Whether the segment from a to b crosses the voxel's plane, allowing `tolerance` voxel sizes
// along the normal on either side (a segment that runs beside the plane closer than that
// crosses it).
bool segmentCrossesVoxelPlane(vec4 plane, vec3 centre, float size, vec3 a, vec3 b,
        float tolerance) {
    float da = voxelPlaneDistance(plane, centre, size, a);
    float db = voxelPlaneDistance(plane, centre, size, b);
    return min(da, db) <= tolerance && max(da, db) >= -tolerance;
}

#endif
