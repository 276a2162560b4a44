// Camera G-buffer of the VPL gather, vertex stage.
#include "../common/frame.glsl"
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

// Bit-identical depth with the depth pre-pass (common/depth_only.frag), another program.
invariant gl_Position;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
