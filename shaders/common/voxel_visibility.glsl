// Visibility between a receiver and a sender through the voxel cascade's occupancy: the atlas
// gather's senders (SEEDS.md section 2, "future work: visibility") and gi/vpl's VPLs. The
// cascade layout is voxel_cascade.glsl's, coverage in the albedo texture's alpha, each voxel's
// surface plane in the normal texture. The segment is walked voxel by voxel through the finest
// level containing each point, each voxel once. An occupied level-0 voxel of one plane, or of
// surfaces meeting at an edge or a corner (voxelMetAtPlane in voxel_plane.glsl), blocks the
// segment only where the segment crosses its mean plane inside the voxel, weighted by its
// coverage: a ray that grazes a wall within a voxel of it, as rays between neighbouring
// receivers near a corner do, passes, and so does a ray passing a block's edge outside it.
// In the occupancy, an edge voxel whose two faces the voxels around it show
// (voxel_edge_faces.glsl) blocks of what crosses its mean plane only what enters the solid
// between its faces: a segment grazing a face beside a block's edge passes. The walk keeps the
// first VOXEL_VISIBILITY_MAX_EDGES such voxels it meets and tests them after it (a software
// rasterizer runs every instruction of the walk's body at every step, taken or not).
// Voxels of surfaces facing apart (both faces of a slab thinner than a voxel) and any voxel of
// a coarser level, whose plane is an average of its children, block by their coverage alone:
// in the occupancy the marches walk (voxel.raster.z), the coverage across the segment's
// direction (directionalCoverage); elsewhere the voxel's coverage, which an unlit voxel holds
// as 1 wherever a surface touches it.
// Both ends first leave their own surface by one voxel along its normal, and the voxels they
// then start in do not block, so a surface never occludes itself (the segment shrunk at both
// ends, epsilon exits against self-hits). Parts of the segment outside the cascade count as
// empty. A segment runs at most 2 l + VOXEL_VISIBILITY_MAX_STEPS (1 + l) +
// VOXEL_VISIBILITY_MAX_EDGES loop iterations with l levels (finestLevel loops over the
// levels): OccupancyVolume::visibilityLoopIterations, which its callers split their work by
// (SHADER_LOOP_ITERATIONS).
#ifndef GI_VOXEL_VISIBILITY_GLSL
#define GI_VOXEL_VISIBILITY_GLSL

#include "voxel_cascade.glsl"
#include "voxel_edge_faces.glsl"
#include "voxel_plane.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelCoverage;
layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelPlane;
layout(binding = BIND_TEX_VOXEL_IRRADIANCE) uniform sampler3D voxelProjectedArea;
layout(binding = BIND_TEX_VOXEL_EDGE_FACES) uniform sampler3D voxelEdgeFaces;

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

// An edge voxel the walk met: its level-0 texel, where the segment enters and leaves it.
struct MetEdge {
    ivec3 texel;
    float enter, leave;
};

// Whether the segment a + dir t, which crosses the mean plane of an edge voxel it met, blocks
// there: at the voxel's two faces where they are known, else at that plane. (Where it passes
// in front of the mean plane it passes the faces too, but for the edge's tip, which the plane
// cuts off; such segments pass, as before the faces were known.)
bool edgeVoxelBlocks(MetEdge e, vec3 a, vec3 dir) {
    vec4 second = texelFetch(voxelEdgeFaces, ivec3(2 * e.texel.x + 1, e.texel.yz), 0);
    if (!edgeFacesKnown(second)) return true;
    vec4 first = texelFetch(voxelEdgeFaces, ivec3(2 * e.texel.x, e.texel.yz), 0);
    float size = levelVoxelSize(0);
    vec3 centre = levelOrigin(0) + (vec3(e.texel) + 0.5) * size;
    return segmentMeetsEdge(first, second, (a + dir * e.enter - centre) / size,
            (a + dir * e.leave - centre) / size);
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
    // Only the occupancy (voxel.raster.z) has its edge voxels' faces.
    bool edgeFaces = voxel.raster.z != 0.0;
    MetEdge firstEdge = MetEdge(ivec3(0), 0.0, 0.0), secondEdge = firstEdge;
    int edges = 0;
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
            } else if (segmentCrossesVoxelPlane(plane, lo + 0.5 * size, size, p, a + dir * exit,
                               kPlaneTolerance)) {
                if (edgeFaces && edges < VOXEL_VISIBILITY_MAX_EDGES &&
                        !voxelHoldsOnePlane(plane, level, false)) {
                    // An edge voxel of level 0 (as voxelMetAtPlane is) that its mean plane
                    // would block: its faces decide after the walk.
                    MetEdge met = MetEdge(texel, t, exit);
                    if (edges == 0) firstEdge = met;
                    else secondEdge = met;
                    ++edges;
                } else {
                    transmittance *= 1.0 - coverage;
                }
            }
        }
        t = exit;
    }
    for (int k = 0; k < edges; ++k) {
        MetEdge e = k == 0 ? firstEdge : secondEdge;
        if (edgeVoxelBlocks(e, a, dir)) {
            transmittance *= 1.0 - clamp(texelFetch(voxelCoverage, e.texel, 0).a, 0.0, 1.0);
        }
    }
    return transmittance;
}

#endif
