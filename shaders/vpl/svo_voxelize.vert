// Octree voxel fragments, vertex stage: world-space attributes straight to the geometry stage.
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

void main() {
    WRITE_VERTEX_DATA(vout)
}
