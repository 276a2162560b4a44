// Surface albedo rho = baseColorFactor x base-colour texture (sRGB-decoded by the texture
// format) x COLOR_0, and the alpha-mask cut-out shared by every pass that draws the scene.
#ifndef GI_MATERIAL_GLSL
#define GI_MATERIAL_GLSL

#include "shared.h"

layout(std430, binding = BIND_SSBO_MATERIALS) readonly buffer MaterialBlock {
    GpuMaterial materials[];
};

layout(binding = BIND_TEX_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(binding = BIND_TEX_EMISSIVE) uniform sampler2D emissiveTexture;

// Index of the current draw's material in `materials`.
layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

// Whether some material of the scene has a texture of `kind` (MATERIAL_TEXTURES_*). A program
// built with FRAME_MATERIAL_TEXTURES (render/FrameSwitches.h) drops the lookups of a kind no
// material has: llvmpipe runs a branch for all pixels of a group whenever one takes it, and a
// texture lookup no pixel needs costs as much as one they do (results-performance.md).
bool materialTexturesOfKind(int kind) {
#ifdef FRAME_MATERIAL_TEXTURES
    return (FRAME_MATERIAL_TEXTURES & kind) != 0;
#else
    return true;
#endif
}

vec4 materialBaseColor(GpuMaterial m, vec2 uv0, vec2 uv1, vec4 vertexColor) {
    vec4 color = m.baseColorFactor * vertexColor;
    if (materialTexturesOfKind(MATERIAL_TEXTURES_BASE_COLOR) && m.flags.x != 0) {
        color *= texture(baseColorTexture, m.flags.w == 1 ? uv1 : uv0);
    }
    return color;
}

vec3 materialEmission(GpuMaterial m, vec2 uv0) {
    vec3 e = m.emissiveAndCutoff.rgb;
    if (materialTexturesOfKind(MATERIAL_TEXTURES_EMISSIVE) &&
            (m.flags.y & MATERIAL_EMISSIVE_TEXTURE) != 0) {
        e *= texture(emissiveTexture, uv0).rgb;
    }
    return e;
}

// Whether the material's emission reaches other surfaces as an area light's direct light.
bool materialEmitsAsLight(GpuMaterial m) {
    return (m.flags.y & MATERIAL_EMITS_AS_LIGHT) != 0;
}

// For passes that shade with the base colour: whether its alpha cuts the fragment out.
bool materialCutOut(GpuMaterial m, float alpha) {
    return m.flags.z == ALPHA_MASK && alpha < m.emissiveAndCutoff.w;
}

// For passes that need no colour: the same cut-out, reading the base colour only for masked
// materials.
bool materialMaskedOut(GpuMaterial m, vec2 uv0, vec2 uv1, vec4 vertexColor) {
    return m.flags.z == ALPHA_MASK &&
           materialCutOut(m, materialBaseColor(m, uv0, uv1, vertexColor).a);
}

#endif
