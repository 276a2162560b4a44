// Vertex stage of the passes that draw the scene's vertices, which GpuScene keeps in world
// space (attribute locations in shared.h): they hand every attribute on unchanged.
#ifndef GI_SCENE_VERTEX_GLSL
#define GI_SCENE_VERTEX_GLSL

#include "shared.h"
#include "vertex_data.glsl"

layout(location = ATTR_POSITION) in vec3 inPosition;
layout(location = ATTR_NORMAL) in vec3 inNormal;
layout(location = ATTR_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTR_TEXCOORD1) in vec2 inTexcoord1;
layout(location = ATTR_COLOR) in vec4 inColor;

// The attributes into the VERTEX_DATA_MEMBERS of output block `to`.
#define WRITE_VERTEX_DATA(to)         \
    to.position = inPosition;         \
    to.normal = inNormal;             \
    to.texcoord0 = inTexcoord0;       \
    to.texcoord1 = inTexcoord1;       \
    to.color = inColor;

#endif
