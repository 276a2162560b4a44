// What the draws of the atlas geometry hand from stage to stage: the scene's vertex data
// (vertex_data.glsl), then what the atlas adds. Each stage declares its block with them, e.g.
// `out AtlasVertex { ATLAS_VERTEX_MEMBERS } vout;`.
#ifndef GI_ATLAS_VERTEX_GLSL
#define GI_ATLAS_VERTEX_GLSL

#include "../common/vertex_data.glsl"

// The G-buffer draws (block AtlasVertex): 1 for double-sided materials.
#define ATLAS_VERTEX_MEMBERS \
    VERTEX_DATA_MEMBERS      \
    float doubleSided;

// The draws from the camera (block ResolveVertex): the atlas coordinate, the chart index and
// 1 for double-sided materials.
#define RESOLVE_VERTEX_MEMBERS \
    VERTEX_DATA_MEMBERS        \
    vec2 atlasUv;              \
    flat float chart;          \
    flat float doubleSided;

#endif
