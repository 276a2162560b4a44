// Shadow maps for every light: a cube map per point light (six 90-degree views storing
// distance / far), a perspective 2D map per spot light (covering its outer cone) and an
// orthographic 2D map per directional light fitted to the scene's bounding sphere. Maps are
// re-rendered only when the lights, the geometry or the settings change, since a static
// scene's shadows do not move with the camera.
// Inputs : GpuScene (world-space vertices, materials for alpha-masked casters), lights.
// Outputs: depth 2D array (DEPTH_COMPONENT32F, compare mode on), depth cube-map array,
//          and the GpuShadow table (one entry per light, same order as GpuLight).
#pragma once

#include "core/Settings.h"
#include "gi/ShadowMaps.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi::render {

class ShadowPass final : public ShadowMaps {
public:
    bool init(gl::ShaderLibrary& shaders, std::string& error);

    // Plans one map per light; allocates only the arrays that some light needs.
    void setLights(const std::vector<scene::Light>& lights, const scene::Aabb& bounds,
            const ShadowSettings& settings);

    struct Inputs {
        const scene::GpuScene& scene;   // world-space casters, materials (alpha-masked ones)
    };
    // Renders the maps (owned here: their layout follows setLights) if anything changed since
    // the last call.
    void execute(const Inputs& in, gl::GpuProfiler& profiler);

    // Binds the maps and the GpuShadow table at their shared.h slots.
    void bind() const override;

    // The kinds of map the planned lights use: bit (1 << SHADOW_2D) for spot and directional
    // maps, (1 << SHADOW_CUBE) for cube maps (FrameSwitches::shadowMaps).
    [[nodiscard]] int mapKinds() const;

    // Forces the next execute to re-render (geometry moved).
    void invalidate() { mDirty = true; }

    // The map sizes setLights(lights, ..., settings) would use, for messages and reports:
    // "shadow.resolution N", and ", suns at shadow.sun_resolution M" when a light is a sun.
    [[nodiscard]] static std::string resolutionText(const std::vector<scene::Light>& lights,
            const ShadowSettings& settings);

    // What setLights(lights, ..., settings) would allocate, before allocating it.
    [[nodiscard]] static std::vector<gl::MemoryItem> memoryFor(const std::vector<scene::Light>& lights,
            const ShadowSettings& settings);

    struct View {
        glm::mat4 viewProjection;
        glm::vec4 lightPositionAndFar;   // w > 0: write distance / far (cube faces)
        int layer;                       // 2D layer, or cube layer * 6 + face
        bool cube;
        bool areaLight = false;          // drawn without the area lights' own surfaces
    };
    // The views setLights planned (exposed for tests).
    const std::vector<View>& views() const { return mViews; }

private:
    gl::ProgramRef mProgram;
    gl::Texture mMaps2D, mMapsCube;
    gl::Buffer mShadowTable;
    gl::Framebuffer mFramebuffer;
    std::vector<View> mViews;
    int mLayers2D = 0, mLayersCube = 0, mResolution2D = 1, mResolutionCube = 1;
    bool mDirty = true;
};

} // namespace gi::render
