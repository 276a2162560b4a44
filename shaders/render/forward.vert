// Forward pass, vertex stage: the scene's vertices are already in world space.
#include "../common/frame.glsl"

layout(location = ATTR_POSITION) in vec3 inPosition;
layout(location = ATTR_NORMAL) in vec3 inNormal;
layout(location = ATTR_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTR_TEXCOORD1) in vec2 inTexcoord1;
layout(location = ATTR_COLOR) in vec4 inColor;

out VertexData {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
} vout;

// Bit-identical depth with the depth pre-pass, which uses another program.
invariant gl_Position;

void main() {
    vout.position = inPosition;
    vout.normal = inNormal;
    vout.texcoord0 = inTexcoord0;
    vout.texcoord1 = inTexcoord1;
    vout.color = inColor;
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
