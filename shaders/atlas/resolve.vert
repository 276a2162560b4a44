// Atlas resolve and debug views, vertex stage: the atlas geometry from the camera, carrying
// each vertex's atlas coordinate (thesis 4.7).
#include "../common/frame.glsl"
#include "../common/scene_vertex.glsl"
#include "atlas_vertex.glsl"

layout(location = ATTR_ATLAS_UV) in vec2 inAtlasUv;
layout(location = ATTR_ATLAS_INFO) in vec2 inAtlasInfo;

out ResolveVertex { RESOLVE_VERTEX_MEMBERS } vout;

void main() {
    WRITE_VERTEX_DATA(vout)
    vout.atlasUv = inAtlasUv;
    vout.chart = inAtlasInfo.x;
    vout.doubleSided = inAtlasInfo.y;
    gl_Position = frame.viewProjection * vec4(inPosition, 1.0);
}
