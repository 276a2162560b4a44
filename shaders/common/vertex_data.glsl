// What a scene draw hands from stage to stage: the world-space surface point and the
// attributes its material reads. Every stage declares its interface block with these
// members, e.g. `out VertexData { VERTEX_DATA_MEMBERS } vout;`, so the stages of a program
// match by construction (a block may add its own members after them).
#ifndef GI_VERTEX_DATA_GLSL
#define GI_VERTEX_DATA_GLSL

#define VERTEX_DATA_MEMBERS \
    vec3 position;          \
    vec3 normal;            \
    vec2 texcoord0;         \
    vec2 texcoord1;         \
    vec4 color;

// Every member of block `from` into block `to` (a geometry stage passing a vertex on).
#define COPY_VERTEX_DATA(to, from)    \
    to.position = from.position;      \
    to.normal = from.normal;          \
    to.texcoord0 = from.texcoord0;    \
    to.texcoord1 = from.texcoord1;    \
    to.color = from.color;

#endif
