// Atlas G-buffer, vertex stage (thesis 4.4): each vertex is placed at its atlas coordinate,
// so rasterisation visits the atlas texels of every triangle. The exact draw sits at depth
// 0.25 and the conservative draw behind it at 0.5, so with GL_LESS the conservative draw only
// fills texels the exact one left empty.
#include "../common/frame.glsl"

layout(location = ATTR_POSITION) in vec3 inPosition;
layout(location = ATTR_NORMAL) in vec3 inNormal;
layout(location = ATTR_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTR_TEXCOORD1) in vec2 inTexcoord1;
layout(location = ATTR_COLOR) in vec4 inColor;
layout(location = ATTR_ATLAS_UV) in vec2 inAtlasUv;
layout(location = ATTR_ATLAS_INFO) in vec2 inAtlasInfo;

out AtlasVertex {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
    float doubleSided;
} vout;

void main() {
    vout.position = inPosition;
    vout.normal = inNormal;
    vout.texcoord0 = inTexcoord0;
    vout.texcoord1 = inTexcoord1;
    vout.color = inColor;
    vout.doubleSided = inAtlasInfo.y;
#ifdef CONSERVATIVE
    const float depth = 0.0;
#else
    const float depth = -0.5;
#endif
    gl_Position = vec4(inAtlasUv * 2.0 - 1.0, depth, 1.0);
}
