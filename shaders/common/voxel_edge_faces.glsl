// The two faces of an edge voxel of the occupancy: a level-0 voxel whose surfaces meet at an
// edge or a corner (voxelMetAtPlane in voxel_plane.glsl, without one plane). Its mean plane
// cuts the edge off between the faces, and beside each face lies air behind that plane which
// segments grazing the face cross; the faces themselves tell that air from the solid.
// voxel/edge_faces.comp finds them in the voxels around the edge voxel that hold one plane
// alone (a face running on from the edge) and stores each as a texel of BIND_TEX_VOXEL_EDGE_FACES:
//   xyz  the face's unit normal, scaled by kConvexEdge or kConcaveEdge (the second face's
//        length 0: no two faces found, the mean plane decides);
//   w    the face's offset from the edge voxel's centre along its normal, in voxel sizes,
//        divided by kEdgeFaceOffsetRange (the face may pass a neighbour's centre).
#ifndef GI_VOXEL_EDGE_FACES_GLSL
#define GI_VOXEL_EDGE_FACES_GLSL

const float kEdgeFaceOffsetRange = 3.0;
// A convex edge (a block's: each face lies behind the other's plane) keeps the normals' length,
// a concave one (a room's corner) halves it.
const float kConvexEdge = 1.0;
const float kConcaveEdge = 0.5;

// A segment meets a face when it comes within this many voxel sizes in front of it: the faces
// come from voxels that hold them alone, to an 8-bit step of the offset, so the mean plane's
// allowance for a surface on a voxel face (kPlaneTolerance) is not needed, and every
// hundredth of a voxel of allowance thickens a block's edge for grazing segments.
const float kEdgeFaceTolerance = 0.03;

vec4 encodeEdgeFace(vec3 normal, float offset, bool convex) {
    return vec4(normal * (convex ? kConvexEdge : kConcaveEdge), offset / kEdgeFaceOffsetRange);
}

bool edgeFacesKnown(vec4 secondFace) {
    return dot(secondFace.xyz, secondFace.xyz) > 0.5 * kConcaveEdge * kConcaveEdge;
}

// The part [lo, hi] of the segment a + t (b - a), t in [0, 1], behind the face or within
// kEdgeFaceTolerance in front of it (lo > hi: none); a and b relative to the voxel's centre,
// in voxel sizes.
vec2 segmentBehindFace(vec4 face, vec3 a, vec3 b) {
    vec3 n = normalize(face.xyz);
    float offset = face.w * kEdgeFaceOffsetRange + kEdgeFaceTolerance;
    float da = dot(n, a) - offset, db = dot(n, b) - offset;
    if (da <= 0.0 && db <= 0.0) return vec2(0.0, 1.0);
    if (da > 0.0 && db > 0.0) return vec2(1.0, 0.0);
    float t = da / (da - db);
    return da <= 0.0 ? vec2(0.0, t) : vec2(t, 1.0);
}

// Whether the segment from a to b (relative to the edge voxel's centre, in voxel sizes) meets
// the solid between its two faces: behind both at a convex edge, behind either at a concave one.
bool segmentMeetsEdge(vec4 first, vec4 second, vec3 a, vec3 b) {
    vec2 behindFirst = segmentBehindFace(first, a, b);
    vec2 behindSecond = segmentBehindFace(second, a, b);
    if (length(first.xyz) > 0.5 * (kConvexEdge + kConcaveEdge)) {
        return max(behindFirst.x, behindSecond.x) <= min(behindFirst.y, behindSecond.y);
    }
    return behindFirst.x <= behindFirst.y || behindSecond.x <= behindSecond.y;
}

#endif
