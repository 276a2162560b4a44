// Reflective shadow map, vertex stage: the scene seen from one view of one light.
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

// The depth pre-pass and the RSM draw use different programs; invariance makes their depths
// bit-identical so the LEQUAL early test keeps exactly the surfaces the light sees.
invariant gl_Position;

layout(location = LOC_RSM_VIEW_PROJECTION) uniform mat4 lightViewProjection;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = lightViewProjection * vec4(inPosition, 1.0);
}
