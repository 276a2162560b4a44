// Shadow-map pass, vertex stage: world-space scene vertices into one shadow view.
#include "../common/scene_vertex.glsl"

layout(location = LOC_SHADOW_VIEW_PROJECTION) uniform mat4 shadowViewProjection;

out VertexData { VERTEX_DATA_MEMBERS } vout;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = shadowViewProjection * vec4(inPosition, 1.0);
}
