// Visibility between a receiver and a sender through the voxel cascade's occupancy: the atlas
// gather's senders (SEEDS.md section 2, "future work: visibility") and gi/vpl's VPLs. The
// cascade layout is voxel_cascade.glsl's, coverage in the albedo texture's alpha, each voxel's
// surface plane in the normal texture. The segment is walked voxel by voxel through the finest
// level containing each point, each voxel once. An occupied level-0 voxel of one plane, or of
// surfaces meeting at an edge or a corner (voxelMetAtPlane in voxel_plane.glsl), blocks the
// segment only where the segment crosses its mean plane inside the voxel, weighted by its
// coverage: a ray that grazes a wall within a voxel of it, as rays between neighbouring
// receivers near a corner do, passes, and so does a ray passing a block's edge outside it.
// An edge voxel's mean plane cuts the edge off, and beside each face lies air behind that plane
// which segments grazing the face cross; where the voxels around it hold the edge's two faces
// (voxelEdgeFaces below), the voxel blocks what enters the solid between them instead.
// Voxels of surfaces facing apart (both faces of a slab thinner than a voxel) and any voxel of
// a coarser level, whose plane is an average of its children, block by their coverage alone:
// in the occupancy the marches walk (voxel.raster.z), the coverage across the segment's
// direction (directionalCoverage); elsewhere the voxel's coverage, which an unlit voxel holds
// as 1 wherever a surface touches it.
// Both ends first leave their own surface by one voxel along its normal, and the voxels they
// then start in do not block, so a surface never occludes itself (the segment shrunk at both
// ends, epsilon exits against self-hits). Parts of the segment outside the cascade count as
// empty. A segment runs at most 2 l + VOXEL_VISIBILITY_MAX_STEPS (1 + l) loop iterations with l
// levels (finestLevel loops over the levels): OccupancyVolume::visibilityLoopIterations, which
// its callers split their work by (SHADER_LOOP_ITERATIONS).
#ifndef GI_VOXEL_VISIBILITY_GLSL
#define GI_VOXEL_VISIBILITY_GLSL

#include "voxel_cascade.glsl"
#include "voxel_plane.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelCoverage;
layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelPlane;
layout(binding = BIND_TEX_VOXEL_IRRADIANCE) uniform sampler3D voxelProjectedArea;

// How much of a voxel of several surfaces a segment along dir meets, from the surfaces' area
// projected onto the voxel's three faces (voxelize.frag), A_i, in face areas: the face the
// segment runs most nearly across, i, sees the surfaces cover A_i of it, and a segment that
// slants across that face by |d_i| / max|d| meets, of what the other faces see, no more than
// that face does (a slab whose two faces lie in the voxel, A = (2, 0, 0), stops every segment
// that crosses it, whatever the angle). A closed object (a column, a block) shows its front
// and its back in each projection, and a segment that meets the one meets the other, so the
// sums count it twice: halved (accuracy-analysis.md measures the choice).
const float kClosedSurfaceProjection = 0.5;

float directionalCoverage(ivec3 texel, vec3 dir) {
    vec3 across = abs(dir);
    vec3 seen = kClosedSurfaceProjection * texelFetch(voxelProjectedArea, texel, 0).rgb * across;
    return clamp(max(seen.x, max(seen.y, seen.z)) / max(across.x, max(across.y, across.z)),
            0.0, 1.0);
}

// The voxels around a voxel, nearest first: 6 sharing a face, 12 an edge, 8 a corner.
const ivec3 kEdgeNeighbours[VOXEL_EDGE_NEIGHBOURS] = ivec3[](
        ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1),
        ivec3(0, 0, -1), ivec3(1, 1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0), ivec3(-1, -1, 0),
        ivec3(1, 0, 1), ivec3(1, 0, -1), ivec3(-1, 0, 1), ivec3(-1, 0, -1), ivec3(0, 1, 1),
        ivec3(0, 1, -1), ivec3(0, -1, 1), ivec3(0, -1, -1), ivec3(1, 1, 1), ivec3(1, 1, -1),
        ivec3(1, -1, 1), ivec3(1, -1, -1), ivec3(-1, 1, 1), ivec3(-1, 1, -1), ivec3(-1, -1, 1),
        ivec3(-1, -1, -1));

// A segment meets an edge's face when it comes within this many voxel sizes in front of it:
// the faces' planes come from voxels that hold them alone, offsets to an 8-bit step (1/127),
// so the mean plane's allowance for a surface on a voxel face (kPlaneTolerance) is not
// needed, and every hundredth of a voxel of it thickens a block's edge for grazing segments.
const float kEdgeFaceTolerance = 0.03;

// Two unit normals closer than this are one face.
const float kSameFace = 0.9;
// The two faces found must explain the voxel's mean normal this well (their mean, whatever
// share of the voxel each covers, lies within 45 degrees of either): else they are not the
// voxel's faces and its mean plane decides.
const float kFacesExplainMean = 0.7;

// An edge or corner voxel's faces: the first two differently oriented planes held alone by
// level-0 voxels around it (a face running on from the edge), as normal and a point on the
// plane. A rotated block's face passes the edge voxel's face neighbours diagonally and may
// share them with the other face, so edge and corner neighbours are searched too.
bool voxelEdgeFaces(ivec3 texel, vec4 plane, vec3 centre, float size, out vec3 n0, out vec3 c0,
        out vec3 n1, out vec3 c1) {
    n0 = vec3(0.0);
    c0 = vec3(0.0);
    n1 = vec3(0.0);
    c1 = vec3(0.0);
    bool first = false;
    ivec3 resolution = ivec3(voxelResolution());
    for (int k = 0; k < VOXEL_EDGE_NEIGHBOURS; ++k) {
        ivec3 neighbour = texel + kEdgeNeighbours[k];
        if (any(lessThan(neighbour, ivec3(0))) || any(greaterThanEqual(neighbour, resolution))) {
            continue;
        }
        vec4 face = texelFetch(voxelPlane, neighbour, 0);
        if (!voxelHoldsOnePlane(face, 0, false)) continue;
        vec3 n = normalize(face.xyz);
        vec3 c = centre + vec3(kEdgeNeighbours[k]) * size + n * (face.w * size);
        if (!first) {
            n0 = n;
            c0 = c;
            first = true;
        } else if (dot(n, n0) < kSameFace && dot(n, n0) > -kSameFace) {
            n1 = n;
            c1 = c;
            vec3 mean = normalize(plane.xyz);
            return dot(normalize(n0 + n1), mean) > kFacesExplainMean;
        }
    }
    return false;
}

// The part [lo, hi] of the segment a + t (b - a), t in [0, 1], behind the plane through c with
// normal n or within `tolerance` voxel sizes in front of it (lo > hi: none).
vec2 segmentBehindPlane(vec3 n, vec3 c, float size, vec3 a, vec3 b, float tolerance) {
    float da = dot(n, a - c) / size - tolerance;
    float db = dot(n, b - c) / size - tolerance;
    if (da <= 0.0 && db <= 0.0) return vec2(0.0, 1.0);
    if (da > 0.0 && db > 0.0) return vec2(1.0, 0.0);
    float t = da / (da - db);
    return da <= 0.0 ? vec2(0.0, t) : vec2(t, 1.0);
}

// Whether the segment a-b meets the solid between an edge voxel's two faces: behind both at a
// convex edge (a block's), behind either at a concave one (a room's corner), where each face
// lies behind the other's plane or in front of it.
bool segmentMeetsEdge(vec3 n0, vec3 c0, vec3 n1, vec3 c1, float size, vec3 a, vec3 b) {
    vec2 behind0 = segmentBehindPlane(n0, c0, size, a, b, kEdgeFaceTolerance);
    vec2 behind1 = segmentBehindPlane(n1, c1, size, a, b, kEdgeFaceTolerance);
    if (dot(n0, c1 - c0) < 0.0) return max(behind0.x, behind1.x) <= min(behind0.y, behind1.y);
    return behind0.x <= behind0.y || behind1.x <= behind1.y;
}

float endOffset(vec3 p) {
    int level = finestLevel(p);
    return level >= 0 ? levelVoxelSize(level) : 0.0;
}

// Distance along dir from p to where it leaves the axis-aligned box [lo, lo + size].
float exitDistance(vec3 p, vec3 dir, vec3 lo, float size) {
    vec3 bound = mix(lo, lo + size, greaterThan(dir, vec3(0.0)));
    vec3 t = (bound - p) / dir;
    t = mix(t, vec3(1e30), lessThan(abs(dir), vec3(1e-12)));
    return max(min(t.x, min(t.y, t.z)), 0.0);
}

float voxelTransmittance(vec3 receiver, vec3 receiverNormal, vec3 sender, vec3 senderNormal) {
    float sizeA = endOffset(receiver), sizeB = endOffset(sender);
    vec3 a = receiver + receiverNormal * sizeA;
    vec3 b = sender + senderNormal * sizeB;
    vec3 d = b - a;
    float len = length(d);
    if (len <= 1e-6 * max(sizeA, sizeB)) return 1.0;
    vec3 dir = d / len;
    float t = 0.0;
    float transmittance = 1.0;
    float coarsest = levelVoxelSize(voxelLevels() - 1);
    int edgesLeft = VOXEL_VISIBILITY_MAX_EDGES;
    for (int i = 0; i < VOXEL_VISIBILITY_MAX_STEPS && t < len && transmittance > 0.01; ++i) {
        vec3 p = a + dir * t;
        int level = finestLevel(p);
        if (level < 0) {
            t += 0.5 * coarsest;
            continue;
        }
        float size = levelVoxelSize(level);
        ivec3 texel = voxelTexel(p, level);
        vec3 lo = levelOrigin(level) + vec3(texel - ivec3(0, 0, level * voxelResolution())) * size;
        // Leave the voxel (a small push past its face keeps the walk from stalling on it).
        float exit = min(t + exitDistance(p, dir, lo, size) + 1e-3 * size, len);
        float coverage = clamp(texelFetch(voxelCoverage, texel, 0).a, 0.0, 1.0);
        // The voxels the two ends start in hold only their own neighbourhood (the surfaces
        // they were pushed off, or a wall meeting them at a corner) and do not block.
        bool endVoxel = i == 0 || exit >= len;
        if (coverage > 0.0 && !endVoxel) {
            vec4 plane = texelFetch(voxelPlane, texel, 0);
            if (!voxelMetAtPlane(plane, level)) {
                transmittance *= 1.0 - (voxel.raster.z != 0.0 ? directionalCoverage(texel, dir)
                                                              : coverage);
            } else {
                vec3 centre = lo + 0.5 * size, q = a + dir * exit;
                vec3 n0, c0, n1, c1;
                bool edge = length(plane.xyz) < kOnePlaneNormal && edgesLeft > 0;
                edgesLeft -= edge ? 1 : 0;
                bool met = edge && voxelEdgeFaces(texel, plane, centre, size, n0, c0, n1, c1)
                        ? segmentMeetsEdge(n0, c0, n1, c1, size, p, q)
                        : segmentCrossesVoxelPlane(plane, centre, size, p, q, kPlaneTolerance);
                if (met) transmittance *= 1.0 - coverage;
            }
        }
        t = exit;
    }
    return transmittance;
}

#endif
