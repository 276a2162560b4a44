// Forward pass, vertex stage: the scene's vertices are already in world space.
#include "../common/frame.glsl"
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

// Bit-identical depth with the depth pre-pass, which uses another program.
invariant gl_Position;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
