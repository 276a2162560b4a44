// Light injection, vertex stage: the scene seen from one light view (thesis 4.3.3.2).
#include "../common/scene_vertex.glsl"
#include "../common/voxel_cascade.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

// The depth pre-pass and the injection draw use different programs; invariance makes their
// depths bit-identical so the LEQUAL early test keeps exactly the visible fragments.
invariant gl_Position;

layout(location = LOC_INJECT_VIEW_PROJECTION) uniform mat4 lightViewProjection;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = lightViewProjection * vec4(inPosition, 1.0);
}
