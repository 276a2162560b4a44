// The GI resources a scene needs (issue: model only what a scene requires). With
// render.plan=fixed the plan reports what the settings allocate as given (the thesis: v^3 x l
// voxels around the camera, an atlas of atlas.resolution^2 texels, a shadow map per light).
// With render.plan=adaptive the sizes follow from the scene:
//   - finest voxel: voxel.size, or the scene's shortest side / voxel.resolution;
//   - a compact scene (its bounds fit in one level of about that size: a Cornell box) gets one
//     scene-centred level holding all of it, so no level covers only the air in front of it;
//   - any other scene (Sponza) gets camera-centred levels, the centre kept inside the scene's
//     bounds, and as many levels as let the coarsest reach every part of the scene from any
//     point of it: levels past that would hold only empty space and are not allocated. The
//     finest level then shrinks until the coarsest just reaches (finer voxels for the same
//     memory), so voxel.size is an upper bound;
//   - light injection: voxel.inject_resolution, or two light-view pixels per finest voxel
//     across the scene's longest side (the thesis' v pixels over the coarsest level leave
//     most finest voxels without a fragment: Sponza's are 0.32 m, its light pixels 1.2 m);
//   - atlas: atlas.texel_size (default half the finest voxel) over the scene's surface area,
//     with room for charts, gutters and packing;
//   - lights whose light cannot reach the scene get no shadow map and no injection: zero
//     power, a spot cone that misses the bounds (both in every plan: they add nothing), or at
//     most 1e-4 of the strongest light's irradiance at the scene's scale.
// Everything here is CPU arithmetic: `voxatlas info` prints a plan without a GL context.
#pragma once

#include "gl/Objects.h"
#include "core/Settings.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi::render {

struct VoxelPlan {
    int resolution = 0;          // v
    int levels = 0;              // l
    float finestExtent = 0.0f;   // edge of level 0, m
    bool sceneCentred = false;
    bool clampCentre = false;
    int injectResolution = 0;    // light-view pixels per side
    int multiplier = 0;          // voxelization raster pixels per voxel edge (0: the setting's)
    int msaa = 1;                // voxel.msaa resolved: samples per raster pixel
    int cones = VOXEL_CONES_RINGS;   // voxel.cones resolved: the adaptive plan's 19, the fixed's 9
    float coneAngle = 0.0f;          // voxel.cone_angle (0: the set's own aperture)
    [[nodiscard]] float voxelSize(int level) const {
        return finestExtent * float(1 << level) / float(resolution);
    }
};

struct ResourcePlan {
    int mode = PLAN_FIXED;
    VoxelPlan voxel;
    int atlasResolution = 0;
    double surfaceArea = 0.0;            // m^2, all instances
    double atlasTexelSize = 0.0;         // m, the texel edge the resolution gives at 50 % fill
    std::vector<int> lights;             // indices of the scene's lights that reach it
    std::vector<std::string> droppedLights;   // "name: why" for each light left out
    // Bytes per resource for each GI mode: voxel textures, atlas textures, shadow maps.
    std::vector<gl::MemoryItem> voxelMemory, atlasMemory, shadowMemory;
    [[nodiscard]] std::size_t voxelBytes() const;
    [[nodiscard]] std::size_t atlasBytes() const;
    [[nodiscard]] std::size_t shadowBytes() const;
};

// The plan for `scene` lit by `lights` at `settings`; `eye` is the start camera (fixed plans
// derive the finest level's edge from it, as the renderer does on the first frame).
[[nodiscard]] ResourcePlan planResources(const scene::Scene& scene,
        const std::vector<scene::Light>& lights, const Settings& settings, const glm::vec3& eye);

// `settings` with the plan's sizes written into them (adaptivePlanKeys()); unchanged for fixed
// plans.
[[nodiscard]] Settings applyPlan(const Settings& settings, const ResourcePlan& plan);

// The --set keys whose values applyPlan replaces under render.plan=adaptive: a value given for
// one of them takes effect only with render.plan=fixed.
[[nodiscard]] const std::vector<std::string>& adaptivePlanKeys();

// The lights the plan keeps, in the scene's order.
[[nodiscard]] std::vector<scene::Light> plannedLights(const std::vector<scene::Light>& lights,
        const ResourcePlan& plan);

// Which of `lights` reach `bounds`, with a reason for each one that does not: lights of zero
// power and spots whose cone misses the bounds never do; with cutoff > 0 neither do lights
// whose irradiance on the bounds stays under cutoff x the strongest light's at the scene's
// scale. Every plan leaves out the first two (they add nothing); the adaptive plan also
// applies kAdaptiveLightCutoff.
[[nodiscard]] std::vector<int> lightsReaching(const std::vector<scene::Light>& lights,
        const scene::Aabb& bounds, double cutoff, std::vector<std::string>* dropped = nullptr);
inline constexpr double kAdaptiveLightCutoff = 1e-4;

// Total world-space triangle area of every instance, m^2.
[[nodiscard]] double sceneSurfaceArea(const scene::Scene& scene);

// Multi-line description for `voxatlas info` and the viewer's overlay; `why` (e.g. "the
// default") follows the plan's name when given.
[[nodiscard]] std::string describePlan(const ResourcePlan& plan, const std::string& why = "");

} // namespace gi::render
