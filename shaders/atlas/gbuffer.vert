// Atlas G-buffer, vertex stage (thesis 4.4): each vertex is placed at its atlas coordinate,
// so rasterisation visits the atlas texels of every triangle. The exact draw sits at depth
// 0.25 and the conservative draw behind it at 0.5, so with GL_LESS the conservative draw only
// fills texels the exact one left empty.
#include "../common/scene_vertex.glsl"
#include "atlas_vertex.glsl"

layout(location = ATTR_ATLAS_UV) in vec2 inAtlasUv;
layout(location = ATTR_ATLAS_INFO) in vec2 inAtlasInfo;

out AtlasVertex { ATLAS_VERTEX_MEMBERS } vout;

void main() {
    WRITE_VERTEX_DATA(vout)
    vout.doubleSided = inAtlasInfo.y;
#ifdef CONSERVATIVE
    const float depth = 0.0;
#else
    const float depth = -0.5;
#endif
    gl_Position = vec4(inAtlasUv * 2.0 - 1.0, depth, 1.0);
}
