// Shadow-map pass, vertex stage: world-space scene vertices into one shadow view.
#include "../common/shared.h"

layout(location = ATTR_POSITION) in vec3 inPosition;
layout(location = ATTR_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTR_TEXCOORD1) in vec2 inTexcoord1;
layout(location = ATTR_COLOR) in vec4 inColor;

layout(location = LOC_SHADOW_VIEW_PROJECTION) uniform mat4 shadowViewProjection;

out ShadowVertex {
    vec3 position;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
} vout;

void main() {
    vout.position = inPosition;
    vout.texcoord0 = inTexcoord0;
    vout.texcoord1 = inTexcoord1;
    vout.color = inColor;
    gl_Position = shadowViewProjection * vec4(inPosition, 1.0);
}
