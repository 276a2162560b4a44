// Voxelization, geometry stage (thesis Listing 4.1): project each triangle orthographically
// along the world axis its face normal is most aligned with, so it covers the most raster
// samples. The projection spans the coarsest level; the raster is v x voxel.multiplier.
#include "../common/vertex_data.glsl"
#include "../common/voxel_cascade.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData { VERTEX_DATA_MEMBERS } vin[];

out VertexData { VERTEX_DATA_MEMBERS } vout;

// |cos| between the face normal and the projection axis: a raster pixel covers
// pixelArea / projectedCosine of the surface.
flat out float projectedCosine;

void main() {
    vec3 faceNormal = abs(cross(vin[1].position - vin[0].position, vin[2].position - vin[0].position));
    float cosine = max(faceNormal.x, max(faceNormal.y, faceNormal.z)) / max(length(faceNormal), 1e-30);
    int coarsest = voxelLevels() - 1;
    vec3 center = levelOrigin(coarsest) + 0.5 * levelExtent(coarsest);
    float halfExtent = 0.5 * levelExtent(coarsest);
    for (int i = 0; i < 3; ++i) {
        vec3 p = (vin[i].position - center) / halfExtent;   // coarsest level -> [-1, 1]^3
        vec3 projected = faceNormal.x >= faceNormal.y && faceNormal.x >= faceNormal.z ? p.yzx
                       : faceNormal.y >= faceNormal.z ? p.zxy : p.xyz;
        gl_Position = vec4(projected.xy, projected.z * 0.5, 1.0);
        COPY_VERTEX_DATA(vout, vin[i])
        projectedCosine = cosine;
        EmitVertex();
    }
    EndPrimitive();
}
