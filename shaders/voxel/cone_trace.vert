// Cone tracing, vertex stage: the scene from the camera at the trace resolution.
#include "../common/frame.glsl"
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
