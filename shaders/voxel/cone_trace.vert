// Cone tracing, vertex stage: the scene from the camera at the trace resolution.
#include "../common/frame.glsl"
#include "../common/scene_vertex.glsl"

out VertexData { VERTEX_DATA_MEMBERS } vout;

// Bit-identical depth with the depth pre-pass (common/depth_only.frag), another program.
invariant gl_Position;

// A strided trace (every second pixel per axis, TraceReusePass.h) shifts the image so each of
// its pixels is centred where the pixel it stands for is; 0 for a full trace.
layout(location = LOC_CONE_TRACE_OFFSET) uniform vec2 traceOffset;

void main() {
    WRITE_VERTEX_DATA(vout)
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
    gl_Position.xy += traceOffset * gl_Position.w;
}
