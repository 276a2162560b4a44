// Light injection, vertex stage: the scene seen from one light view (thesis 4.3.3.2).
#include "voxel_common.glsl"

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

// The depth pre-pass and the injection draw use different programs; invariance makes their
// depths bit-identical so the LEQUAL early test keeps exactly the visible fragments.
invariant gl_Position;

void main() {
    vout.position = inPosition;
    vout.normal = inNormal;
    vout.texcoord0 = inTexcoord0;
    vout.texcoord1 = inTexcoord1;
    vout.color = inColor;
    gl_Position = voxel.viewProjection * vec4(inPosition, 1.0);
}
