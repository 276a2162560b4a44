// Per-view uniforms and the scene's light and material tables (layouts in shared.h).
#include "shared.h"

layout(std140, binding = BIND_UBO_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};

layout(std430, binding = BIND_SSBO_LIGHTS) readonly buffer LightBlock {
    GpuLight lights[];
};

layout(std430, binding = BIND_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};
