// Atlas resolve and debug views, vertex stage: the atlas geometry from the camera, carrying
// each vertex's atlas coordinate (thesis 4.7).
#include "../common/frame.glsl"

layout(location = ATTR_POSITION) in vec3 inPosition;
layout(location = ATTR_NORMAL) in vec3 inNormal;
layout(location = ATTR_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTR_TEXCOORD1) in vec2 inTexcoord1;
layout(location = ATTR_COLOR) in vec4 inColor;
layout(location = ATTR_ATLAS_UV) in vec2 inAtlasUv;
layout(location = ATTR_ATLAS_INFO) in vec2 inAtlasInfo;

out ResolveVertex {
    vec3 position;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
    vec2 atlasUv;
    flat float chart;
} vout;

void main() {
    vout.position = inPosition;
    vout.texcoord0 = inTexcoord0;
    vout.texcoord1 = inTexcoord1;
    vout.color = inColor;
    vout.atlasUv = inAtlasUv;
    vout.chart = inAtlasInfo.x;
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
