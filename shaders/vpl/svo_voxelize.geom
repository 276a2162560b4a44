// Octree voxel fragments, geometry stage (Crassin and Green 2012): each triangle is projected
// orthographically along the world axis its normal is most aligned with, onto a raster over
// the octree's cube of svo.shape.z pixels a side (a few per leaf voxel, so thin triangles
// still leave fragments).
#include "../common/svo.glsl"
#include "../common/vertex_data.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData { VERTEX_DATA_MEMBERS } vin[];

out VertexData { VERTEX_DATA_MEMBERS } vout;

void main() {
    vec3 faceNormal = abs(cross(vin[1].position - vin[0].position,
            vin[2].position - vin[0].position));
    float halfSide = 0.5 * float(svoResolution());
    for (int i = 0; i < 3; ++i) {
        vec3 p = (svoFromWorld(vin[i].position) - halfSide) / halfSide;   // the cube -> [-1, 1]^3
        vec3 projected = faceNormal.x >= faceNormal.y && faceNormal.x >= faceNormal.z ? p.yzx
                       : faceNormal.y >= faceNormal.z ? p.zxy : p.xyz;
        gl_Position = vec4(projected.xy, projected.z * 0.5, 1.0);
        COPY_VERTEX_DATA(vout, vin[i])
        EmitVertex();
    }
    EndPrimitive();
}
