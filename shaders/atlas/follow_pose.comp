// Moves the atlas' vertices with the scene's animated instances: every atlas vertex takes the
// world position and normal of the GpuScene vertex it was split from (AtlasVertex::source),
// which GpuScene::updateDynamic has posed. Atlas coordinates stay: rigid motion keeps each
// chart's shape, and the G-buffer measures every texel's area again.
#include "../common/shared.h"

layout(local_size_x = ATLAS_POSE_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_SCENE_VERTICES) readonly buffer SceneVertices {
    float sceneVertex[];
};
layout(std430, binding = BIND_SSBO_ATLAS_VERTICES) buffer AtlasVertices {
    float atlasVertex[];
};
layout(std430, binding = BIND_SSBO_ATLAS_SOURCES) readonly buffer Sources {
    uint source[];
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(source.length())) return;
    uint from = source[i] * uint(SCENE_VERTEX_FLOATS);
    uint to = i * uint(ATLAS_VERTEX_FLOATS);
    // position (3 floats) then normal (3 floats) lead both layouts.
    for (uint k = 0u; k < 6u; ++k) atlasVertex[to + k] = sceneVertex[from + k];
}
