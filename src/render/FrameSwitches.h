// The frame's switches as the shaders read them (shaders/common/frame.glsl: shadingModel(),
// shadowMethod(), shadowsApplied(), shadowMapsOfKind(); material.glsl:
// materialTexturesOfKind(); lighting.glsl: lightsOfKind()): written into the frame uniforms
// every frame (the kinds of shadow map, material texture and light excepted), and given as
// #defines to the passes that compile a program per setting of them (gl/ProgramVariants.h).
#pragma once

#include "core/Settings.h"
#include "gl/Shared.h"

#include <string>
#include <vector>

namespace gi::render {

struct FrameSwitches {
    int shadingModel = 0;   // SHADING_*
    int shadowMethod = 0;   // SHADOW_METHOD_*
    bool shadows = true;    // shadow.enabled
    // Bit (1 << SHADOW_2D) and (1 << SHADOW_CUBE): the kinds of shadow map some light has
    // (ShadowPass::mapKinds); the filter of a kind no light has is compiled out.
    int shadowMaps = ~0;
    // MATERIAL_TEXTURES_* bits: the kinds of texture some material has
    // (GpuScene::textureKinds); the lookups of a kind no material has are compiled out.
    int materialTextures = ~0;
    // Bit (1 << LIGHT_*) for every kind of light the scene has (GpuScene::lightKinds); the
    // code of the other kinds is compiled out.
    int lightKinds = ~0;
    int upsample = UPSAMPLE_DEPTH;   // UPSAMPLE_*: how the indirect texture is upsampled

    [[nodiscard]] static FrameSwitches of(const Settings& settings);
    // FRAME_SHADING_MODEL, FRAME_SHADOW_METHOD, FRAME_SHADOWS, FRAME_SHADOW_MAPS,
    // FRAME_MATERIAL_TEXTURES, FRAME_LIGHT_KINDS, FRAME_UPSAMPLE.
    [[nodiscard]] std::vector<std::string> defines() const;
};

} // namespace gi::render
