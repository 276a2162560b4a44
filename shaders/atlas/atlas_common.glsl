// The atlas passes' uniform block (layout in shared.h).
#ifndef GI_ATLAS_COMMON_GLSL
#define GI_ATLAS_COMMON_GLSL

#include "../common/shared.h"

layout(std140, binding = BIND_UBO_ATLAS) uniform AtlasBlock {
    AtlasUniforms atlas;
};

#endif
