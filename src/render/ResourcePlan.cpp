#include "render/ResourcePlan.h"

#include "gi/atlas/AtlasSenderSamplingPass.h"
#include "gi/atlas/AtlasTextures.h"
#include "gi/voxel/CascadeVolume.h"
#include "gi/voxel/ConeSet.h"
#include "gi/voxel/VoxelTextures.h"
#include "render/ShadowPass.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gi::render {
namespace {

// A scene is compact when its bounds (with the snapping room finestExtentCovering adds) fit
// in one level at most this much larger than the planned finest level.
constexpr float kCompactSlack = 1.25f;
// Share of the atlas' texels covered by charts, gutters and packing waste left aside.
constexpr double kAtlasFill = 0.5;
// Light-view pixels per finest voxel edge for injection, and the most an adaptive plan asks
// for (a light's views are rasterized at this size whenever its light changes).
constexpr float kInjectPixelsPerVoxel = 4.0f;
constexpr int kMaxAdaptiveInject = 1024;
// Voxelization raster samples per pixel on the adaptive plan (voxel.msaa): the least every
// OpenGL 4.5 implementation offers (GL_MAX_FRAMEBUFFER_SAMPLES >= 4).
constexpr int kAdaptiveVoxelizeSamples = 4;

std::size_t sum(const std::vector<gl::MemoryItem>& items) {
    std::size_t total = 0;
    for (const gl::MemoryItem& item : items) total += item.bytes;
    return total;
}

float distanceToBox(const glm::vec3& p, const scene::Aabb& box) {
    return glm::length(glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f)));
}

double mebibytes(std::size_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

std::string formatCutoff(double cutoff) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", cutoff);
    return text;
}

VoxelPlan fixedVoxelPlan(const scene::Aabb& bounds, const VoxelSettings& s, const glm::vec3& eye) {
    VoxelPlan plan;
    plan.resolution = s.resolution;
    plan.levels = s.levels;
    plan.sceneCentred = s.sceneCentred;
    plan.clampCentre = s.clampCentre;
    plan.finestExtent = s.extent > 0.0f ? s.extent
                        : s.sceneCentred ? voxel::CascadeVolume::finestExtentCovering(bounds)
                                         : voxel::CascadeVolume::finestExtentFor(bounds, eye, s.levels);
    return plan;
}

VoxelPlan adaptiveVoxelPlan(const scene::Aabb& bounds, const VoxelSettings& s) {
    VoxelPlan plan;
    plan.resolution = s.resolution;
    const float v = float(s.resolution);
    if (bounds.empty()) {
        plan.levels = 1;
        plan.sceneCentred = true;
        plan.finestExtent = s.size > 0.0f ? s.size * v : 1.0f;
        return plan;
    }
    const glm::vec3 size = bounds.size();
    const float longest = std::max(size.x, std::max(size.y, size.z));
    // A flat scene (a floor) has no thickness to size voxels by: use an eighth of its span.
    const float shortest = std::max(std::min(size.x, std::min(size.y, size.z)), longest / 8.0f);
    const float finestVoxel = s.size > 0.0f ? s.size : std::max(shortest, 1e-9f) / v;
    const float finest = finestVoxel * v;   // at most this: the plan may make it finer
    const float covering = voxel::CascadeVolume::finestExtentCovering(bounds);
    if (covering <= kCompactSlack * finest) {
        plan.levels = 1;
        plan.sceneCentred = true;
        plan.finestExtent = covering;
        return plan;
    }
    // A scene that one level of at most voxel.one_level_limit^3 voxels holds at that voxel
    // gets the one level rather than a cascade: a cone then meets every surface at the finest
    // voxel, a thin wall is a whole voxel thick wherever a cone meets it, and the light a
    // surface receives no longer changes with the level that holds it as the camera moves
    // (accuracy-analysis.md: the thin-wall leak 7.9 % -> 2.3 %, Sponza's arcade 0.63 -> 0.35).
    const auto oneLevelOf = [&](int resolution) {
        plan.resolution = resolution;
        plan.levels = 1;
        plan.sceneCentred = true;
        plan.finestExtent = covering;
        // The raster keeps the size the setting gives the base resolution (v x multiplier
        // pixels a side), so voxelizing the one level costs what one raster of the cascade
        // did; at 2 pixels per voxel edge its voxel.msaa samples per pixel find the thin
        // surfaces that injection's light views (4 pixels per voxel edge) light
        // (accuracy-analysis.md, 'Voxelization with four samples a pixel').
        plan.multiplier = std::max(s.resolution * s.multiplier / resolution, 1);
        return plan;
    };
    int oneLevel = s.resolution;
    while (oneLevel < s.oneLevelLimit && float(oneLevel) * finestVoxel < covering) oneLevel *= 2;
    if (oneLevel <= s.oneLevelLimit && float(oneLevel) * finestVoxel >= covering) {
        return oneLevelOf(oneLevel);
    }
    // So does a scene that the largest such level holds at up to twice that voxel: a cascade
    // would give it that voxel only in its finest level's box around the camera, its second
    // level's voxel (twice as coarse) beyond, and coarser ones further out, where the one level
    // keeps it everywhere; and only one level lets the light pyramid keep each face apart
    // (accuracy-analysis.md: the open-front box 0.498 -> 0.279).
    if (s.oneLevelLimit >= s.resolution &&
            2.0f * float(s.oneLevelLimit) * finestVoxel >= covering) {
        return oneLevelOf(s.oneLevelLimit);
    }
    // The centre stays inside the bounds, so the coarsest level reaches all of them from
    // anywhere once it spans twice the longest side (with finestExtentFor's snapping slack).
    const float coarsest = 2.0f * longest * 1.1f;
    const int maxLevels = voxel::CascadeVolume::kMaxLevels;
    const int levels = 1 + int(std::ceil(std::log2(coarsest / finest) - 1e-6f));
    // Rounding the level count up leaves the coarsest level larger than needed; spend that
    // slack on finer voxels instead: the finest level shrinks until the coarsest just reaches.
    plan.clampCentre = true;
    plan.levels = std::clamp(levels, 1, maxLevels);
    plan.finestExtent = coarsest / float(1 << (plan.levels - 1));
    return plan;
}

// Light-view pixels for injection: a fragment lands in one finest voxel, so a light pixel
// larger than the finest voxel leaves voxels between fragments dark (rows of lit and unlit
// voxels across a sunlit floor). Four pixels per finest voxel across the longest side: with
// two, which voxel a pixel's flux lands in still aliased with the view's size enough to move
// Sponza's indirect energy by 4 % between neighbouring sizes; from four it holds
// (accuracy-analysis.md, 'Light injection summed in fixed point, four pixels per voxel').
int adaptiveInjectResolution(const scene::Aabb& bounds, const VoxelPlan& plan,
        const VoxelSettings& s) {
    if (s.injectResolution > 0) return s.injectResolution;
    const glm::vec3 size = bounds.size();
    const float longest = std::max(size.x, std::max(size.y, size.z));
    const float pixels = kInjectPixelsPerVoxel * longest / std::max(plan.voxelSize(0), 1e-9f);
    return std::clamp(int(std::ceil(std::min(pixels, 1e6f))), plan.resolution, kMaxAdaptiveInject);
}

} // namespace

std::size_t ResourcePlan::voxelBytes() const { return sum(voxelMemory); }
std::size_t ResourcePlan::atlasBytes() const { return sum(atlasMemory); }
std::size_t ResourcePlan::shadowBytes() const { return sum(shadowMemory); }

double sceneSurfaceArea(const scene::Scene& scene) {
    double area = 0.0;
    for (const scene::Instance& instance : scene.instances) {
        const scene::Primitive& p = scene.primitives[std::size_t(instance.primitive)];
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const glm::dvec3 a(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t]], 1.0f));
            const glm::dvec3 b(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t + 1]], 1.0f));
            const glm::dvec3 c(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t + 2]], 1.0f));
            area += 0.5 * glm::length(glm::cross(b - a, c - a));
        }
    }
    return area;
}

std::vector<int> lightsReaching(const std::vector<scene::Light>& lights, const scene::Aabb& bounds,
        double cutoff, std::vector<std::string>* dropped) {
    auto drop = [&](const scene::Light& light, std::size_t i, const std::string& why) {
        if (dropped) {
            dropped->push_back((light.name.empty() ? "light " + std::to_string(i) : light.name) +
                               ": " + why);
        }
    };
    std::vector<int> kept;
    if (bounds.empty()) {
        for (std::size_t i = 0; i < lights.size(); ++i) kept.push_back(int(i));
        return kept;
    }
    const glm::vec3 centre = bounds.center();
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-9f);
    auto power = [](const scene::Light& l) { return scene::lightStrength(l); };
    // The strongest irradiance any light gives at the scene's scale: point and spot lights at
    // the larger of their distance to the centre and the scene's radius.
    double strongest = 0.0;
    for (const scene::Light& l : lights) {
        if (scene::isDistant(l.type)) {
            strongest = std::max(strongest, power(l));
        } else {
            const double d = std::max(glm::length(l.position - centre), radius);
            strongest = std::max(strongest, power(l) / (d * d));
        }
    }
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const scene::Light& l = lights[i];
        if (!(power(l) > 0.0)) {
            drop(l, i, "emits nothing");
            continue;
        }
        if (!scene::isDistant(l.type)) {
            const float d = distanceToBox(l.position, bounds);
            if (l.type == scene::LightType::Spot && d > 0.0f) {
                const glm::vec3 toCentre = centre - l.position;
                const float distance = glm::length(toCentre);
                const float halfAngle = distance > radius ? std::asin(radius / distance)
                                                          : glm::pi<float>();
                const float angle = std::acos(std::clamp(
                        glm::dot(glm::normalize(toCentre), glm::normalize(l.direction)), -1.0f, 1.0f));
                if (angle - halfAngle > l.outerConeAngle) {
                    drop(l, i, "its cone misses the scene");
                    continue;
                }
            }
            if (d > 0.0f && power(l) / (double(d) * double(d)) < cutoff * strongest) {
                drop(l, i, "under " + formatCutoff(cutoff) +
                                   " of the strongest light's irradiance on the scene");
                continue;
            }
        }
        kept.push_back(int(i));
    }
    return kept;
}

ResourcePlan planResources(const scene::Scene& scene, const std::vector<scene::Light>& lights,
        const Settings& settings, const glm::vec3& eye) {
    ResourcePlan plan;
    plan.mode = settings.plan;
    plan.surfaceArea = sceneSurfaceArea(scene);
    if (settings.plan == PLAN_ADAPTIVE) {
        plan.voxel = adaptiveVoxelPlan(scene.bounds, settings.voxel);
        plan.voxel.injectResolution =
                adaptiveInjectResolution(scene.bounds, plan.voxel, settings.voxel);
        const double texel = settings.atlas.texelSize > 0.0f
                ? double(settings.atlas.texelSize)
                : 0.5 * double(plan.voxel.voxelSize(0));
        const double side = std::sqrt(plan.surfaceArea / kAtlasFill) / texel;
        const int rounded = int(std::ceil(std::min(side, 1e6) / 64.0)) * 64;
        plan.atlasResolution = std::clamp(rounded, 64, 4096);
        plan.lights = lightsReaching(lights, scene.bounds, kAdaptiveLightCutoff, &plan.droppedLights);
    } else {
        plan.voxel = fixedVoxelPlan(scene.bounds, settings.voxel, eye);
        plan.atlasResolution = settings.atlas.resolution;
        // Only the lights that add nothing at all: the image stays exactly the same.
        plan.lights = lightsReaching(lights, scene.bounds, 0.0, &plan.droppedLights);
    }
    plan.atlasTexelSize = plan.atlasResolution > 0
            ? std::sqrt(plan.surfaceArea / kAtlasFill) / double(plan.atlasResolution)
            : 0.0;
    plan.voxelMemory = voxel::VoxelTextures::memoryFor(plan.voxel.resolution, plan.voxel.levels,
            settings.voxel.anisotropic, settings.giBounces > 1);
    bool dynamic = false;
    for (const scene::Instance& instance : scene.instances) dynamic |= instance.dynamic;
    if (dynamic && settings.voxel.cache) {
        // StaticVoxelCache: albedo, normal, irradiance, lock copies (and the directional one).
        const int v = plan.voxel.resolution;
        const glm::ivec3 size(v, v, v * plan.voxel.levels);
        const std::size_t directional = settings.voxel.anisotropic
                ? gl::textureBytes(GL_RGBA16F, {v * VOXEL_FACES, v, v * plan.voxel.levels}, 1)
                : 0;
        plan.voxelMemory.push_back({"voxel/static", gl::textureBytes(GL_RGBA16F, size, 1) * 2 +
                                                            gl::textureBytes(GL_RGBA8_SNORM, size, 1) +
                                                            gl::textureBytes(GL_R32UI, size, 1) +
                                                            directional});
    }
    // The 19 cones read the voxels at finer mips than the thesis' 9: on the fixed plan's coarse
    // voxels (9 cm in the Cornell box) that scores worse (relative RMSE 0.51 -> 0.61,
    // accuracy-analysis.md), so the fixed plan keeps the thesis' 9.
    plan.voxel.cones = settings.voxel.cones != VOXEL_CONES_PLAN ? settings.voxel.cones
            : plan.mode == PLAN_ADAPTIVE                        ? VOXEL_CONES_RINGS
                                                                : VOXEL_CONES_THESIS;
    plan.voxel.coneAngle = settings.voxel.coneAngle;
    // Four samples per raster pixel find the thin and curved surfaces that two pixels per
    // voxel edge miss and injection's light views light (Sponza's sun: energy 0.848 -> 0.896,
    // accuracy-analysis.md); the fixed plan voxelizes as the thesis does, one sample a pixel.
    plan.voxel.msaa = settings.voxel.msaa != 0 ? settings.voxel.msaa
            : plan.mode == PLAN_ADAPTIVE       ? kAdaptiveVoxelizeSamples
                                               : 1;
    plan.atlasMemory = atlas::AtlasTextures::memoryFor(
            plan.atlasResolution, atlas::AtlasTextures::needsBackSides(scene),
            settings.giBounces);
    for (gl::MemoryItem& item : atlas::AtlasSenderSamplingPass::importanceMemoryFor(
                 settings.atlas, plan.atlasResolution)) {
        plan.atlasMemory.push_back(std::move(item));
    }
    plan.shadowMemory = ShadowPass::memoryFor(plannedLights(lights, plan), settings.shadow);
    return plan;
}

Settings applyPlan(const Settings& settings, const ResourcePlan& plan) {
    Settings s = settings;
    s.voxel.cones = plan.voxel.cones;
    s.voxel.msaa = plan.voxel.msaa;
    if (plan.mode != PLAN_ADAPTIVE) return s;
    s.voxel.resolution = plan.voxel.resolution;
    if (plan.voxel.multiplier > 0) s.voxel.multiplier = plan.voxel.multiplier;
    s.voxel.levels = plan.voxel.levels;
    s.voxel.extent = plan.voxel.finestExtent;
    s.voxel.sceneCentred = plan.voxel.sceneCentred;
    s.voxel.clampCentre = plan.voxel.clampCentre;
    s.voxel.injectResolution = plan.voxel.injectResolution;
    s.atlas.resolution = plan.atlasResolution;
    return s;
}

const std::vector<std::string>& adaptivePlanKeys() {
    static const std::vector<std::string> keys = {"voxel.cascades", "voxel.extent",
            "voxel.scene_centred", "voxel.clamp_centre", "atlas.resolution"};
    return keys;
}

std::vector<scene::Light> plannedLights(const std::vector<scene::Light>& lights,
        const ResourcePlan& plan) {
    std::vector<scene::Light> kept;
    for (const int i : plan.lights) {
        if (i >= 0 && std::size_t(i) < lights.size()) kept.push_back(lights[std::size_t(i)]);
    }
    return kept;
}

std::string describePlan(const ResourcePlan& plan, const std::string& why) {
    char line[256];
    std::string text = std::string("plan       ") +
            (plan.mode == PLAN_ADAPTIVE ? "adaptive (sized from the scene)"
                                        : "fixed (the settings as given)") +
            (why.empty() ? "" : ": " + why) + "\n";
    const VoxelPlan& v = plan.voxel;
    std::snprintf(line, sizeof line,
            "  voxel    %d^3 x %d level%s, %s, finest voxel %.4g m, coarsest level %.4g m: %.2f MiB\n",
            v.resolution, v.levels, v.levels == 1 ? "" : "s",
            v.sceneCentred ? "centred on the scene"
                           : (v.clampCentre ? "centred on the camera (kept inside the scene)"
                                            : "centred on the camera"),
            double(v.voxelSize(0)), double(v.finestExtent * float(1 << (v.levels - 1))),
            mebibytes(plan.voxelBytes()));
    text += line;
    if (v.multiplier > 0) {
        std::snprintf(line, sizeof line,
                "           voxelized through a %d^2-pixel raster (%d pixels per voxel edge, %d "
                "sample%s a pixel)\n",
                v.resolution * v.multiplier, v.multiplier, v.msaa, v.msaa == 1 ? "" : "s");
        text += line;
    } else {
        std::snprintf(line, sizeof line, "           voxelized with %d sample%s a raster pixel\n",
                v.msaa, v.msaa == 1 ? "" : "s");
        text += line;
    }
    if (v.injectResolution > 0) {
        std::snprintf(line, sizeof line, "           light injection through %d^2-pixel light views\n",
                v.injectResolution);
        text += line;
    }
    const voxel::ConeSet cones = voxel::coneSet(v.cones, v.coneAngle);
    std::snprintf(line, sizeof line, "           %d diffuse cones (1",
            cones.conesPerPixel(1));
    text += line;
    for (const voxel::ConeRing& ring : cones.rings) {
        if (ring.count > 0) text += " + " + std::to_string(ring.count);
    }
    std::snprintf(line, sizeof line, ") of %.3g degrees (voxel.cones)\n",
            double(cones.apertureDegrees));
    text += line;
    std::snprintf(line, sizeof line,
            "  atlas    %d^2 texels over %.4g m^2 of surface (about %.3g m per texel): %.2f MiB\n",
            plan.atlasResolution, plan.surfaceArea, plan.atlasTexelSize, mebibytes(plan.atlasBytes()));
    text += line;
    std::snprintf(line, sizeof line, "  lights   %zu with shadow maps and injection: %.2f MiB\n",
            plan.lights.size(), mebibytes(plan.shadowBytes()));
    text += line;
    for (const std::string& why : plan.droppedLights) text += "           left out: " + why + "\n";
    return text;
}

} // namespace gi::render
