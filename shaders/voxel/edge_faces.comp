// Each edge voxel's two faces in the occupancy's level 0 (EdgeFacesPass.h,
// common/voxel_edge_faces.glsl), one invocation per voxel: the first two differently oriented
// planes held alone by the voxels around it, nearest first. A rotated block's face passes the
// edge voxel's face neighbours diagonally and may share them with the other face, so the
// neighbours across its edges and corners are searched too. The two faces must explain the
// voxel's mean normal (their mean, whatever share of the voxel each covers, within 45 degrees
// of it), else they are not its faces.
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"
#include "../common/voxel_edge_faces.glsl"

layout(local_size_x = VOXEL_LOCAL_SIZE, local_size_y = VOXEL_LOCAL_SIZE, local_size_z = VOXEL_LOCAL_SIZE) in;

layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelPlane;
layout(binding = BIND_IMG_VOXEL_EDGE_FACES, rgba8_snorm) uniform writeonly image3D edgeFaces;

// The voxels around one, nearest first: 6 sharing a face, 12 an edge, 8 a corner.
const int kNeighbours = 26;
const ivec3 kNeighbour[kNeighbours] = ivec3[](
        ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1),
        ivec3(0, 0, -1), ivec3(1, 1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0), ivec3(-1, -1, 0),
        ivec3(1, 0, 1), ivec3(1, 0, -1), ivec3(-1, 0, 1), ivec3(-1, 0, -1), ivec3(0, 1, 1),
        ivec3(0, 1, -1), ivec3(0, -1, 1), ivec3(0, -1, -1), ivec3(1, 1, 1), ivec3(1, 1, -1),
        ivec3(1, -1, 1), ivec3(1, -1, -1), ivec3(-1, 1, 1), ivec3(-1, 1, -1), ivec3(-1, -1, 1),
        ivec3(-1, -1, -1));

// Two unit normals closer than this are one face (or a slab's two faces, facing apart).
const float kSameFace = 0.9;
// How well the two faces must explain the voxel's mean normal.
const float kFacesExplainMean = 0.7;

void main() {
    int v = voxelResolution();
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, ivec3(v)))) return;
    vec4 plane = texelFetch(voxelPlane, texel, 0);
    vec4 first = vec4(0.0), second = vec4(0.0);
    bool edge = voxelOccupied(plane) && voxelMetAtPlane(plane, 0) &&
                !voxelHoldsOnePlane(plane, 0, false);
    vec3 n0 = vec3(0.0), p0 = vec3(0.0);
    bool found = false;
    for (int k = 0; k < kNeighbours && edge; ++k) {
        ivec3 neighbour = texel + kNeighbour[k];
        if (any(lessThan(neighbour, ivec3(0))) || any(greaterThanEqual(neighbour, ivec3(v)))) {
            continue;
        }
        vec4 face = texelFetch(voxelPlane, neighbour, 0);
        if (!voxelHoldsOnePlane(face, 0, false)) continue;
        vec3 n = normalize(face.xyz);
        // The point of the face nearest the neighbour's centre, which lies on the face, from
        // the edge voxel's centre in voxel sizes.
        vec3 p = vec3(kNeighbour[k]) + n * face.w;
        if (!found) {
            n0 = n;
            p0 = p;
            found = true;
        } else if (abs(dot(n, n0)) < kSameFace) {
            if (dot(normalize(n0 + n), normalize(plane.xyz)) > kFacesExplainMean) {
                // Convex where the second face lies behind the first's plane.
                bool convex = dot(n0, p - p0) < 0.0;
                first = encodeEdgeFace(n0, dot(n0, p0), convex);
                second = encodeEdgeFace(n, dot(n, p), convex);
            }
            break;
        }
    }
    imageStore(edgeFaces, ivec3(2 * texel.x, texel.yz), first);
    imageStore(edgeFaces, ivec3(2 * texel.x + 1, texel.yz), second);
}
