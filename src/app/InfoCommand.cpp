#include "app/InfoCommand.h"

#include "app/SceneSetup.h"
#include "gi/vpl/VplReport.h"
#include "gl/Shared.h"
#include "render/ResourcePlan.h"
#include "render/ShadowMethodReport.h"
#include "scene/Animation.h"
#include "scene/GpuScene.h"
#include "scene/LightViews.h"

#include <glm/gtc/constants.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace gi::app {
namespace {

const char* lightTypeName(scene::LightType type) {
    switch (type) {
    case scene::LightType::Point: return "point";
    case scene::LightType::Spot: return "spot";
    case scene::LightType::Directional: return "directional";
    case scene::LightType::Area: return "area";
    case scene::LightType::Sky: return "sky";
    }
    return "?";
}

double mebibytes(std::size_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

// Counts, bounds, recentring and animation of the loaded scene.
void printContents(const scene::Scene& scene, double loadSeconds) {
    std::printf("scene      %s\n", scene.sourcePath.c_str());
    std::printf("load time  %.3f s (parse, buffers, texture decoding, validation, defaults)\n", loadSeconds);
    std::printf("triangles  %zu\n", scene.triangleCount());
    std::printf("vertices   %zu\n", scene.vertexCount());
    std::printf("primitives %zu (%zu instances)\n", scene.primitives.size(), scene.instances.size());
    std::printf("materials  %zu\n", scene.materials.size());
    std::printf("textures   %zu\n", scene.textures.size());
    if (scene.bounds.empty()) {
        std::printf("bounds     empty\n");
    } else {
        const glm::vec3 size = scene.bounds.size();
        std::printf("bounds     min (%.4g, %.4g, %.4g) max (%.4g, %.4g, %.4g) size %.4g x %.4g x %.4g m\n",
                scene.bounds.min.x, scene.bounds.min.y, scene.bounds.min.z, scene.bounds.max.x,
                scene.bounds.max.y, scene.bounds.max.z, size.x, size.y, size.z);
    }
    if (scene.origin != glm::vec3(0.0f)) {
        std::printf("origin     (%.9g, %.9g, %.9g): far from the file's origin, so positions here\n"
                    "           are relative to this point (float precision, scene/Recentre.h)\n",
                scene.origin.x, scene.origin.y, scene.origin.z);
    }
    if (!scene.animations.empty()) {
        std::size_t dynamic = 0;
        for (const scene::Instance& instance : scene.instances) dynamic += instance.dynamic ? 1 : 0;
        std::printf("animations %zu, %.3g s loop; %zu of %zu instances dynamic (bounds cover "
                    "every pose)\n",
                scene.animations.size(), double(scene::animationDuration(scene)), dynamic,
                scene.instances.size());
    }
}

void printLights(const scene::Scene& scene, const std::string& why) {
    std::printf("lights     %zu\n", scene.lights.size());
    if (!why.empty()) std::printf("  chosen: %s\n", why.c_str());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& l = scene.lights[i];
        std::printf("  [%zu] %-11s %s colour (%.3g, %.3g, %.3g) intensity %.4g", i,
                lightTypeName(l.type), l.isDefault ? "(default)" : l.name.c_str(), l.color.r,
                l.color.g, l.color.b, l.intensity);
        if (l.type == scene::LightType::Area) {
            float area = 0.0f;
            for (const scene::EmitterTriangle& t : l.emitters) area += t.area();
            std::printf(" %zu triangle(s), %.4g m^2, centre (%.4g, %.4g, %.4g)\n", l.emitters.size(),
                    area, l.position.x, l.position.y, l.position.z);
            continue;
        }
        if (l.type == scene::LightType::Sky) {
            std::printf(" (radiance colour x intensity from every unblocked direction)\n");
            continue;
        }
        if (l.type != scene::LightType::Directional) {
            std::printf(" at (%.4g, %.4g, %.4g)", l.position.x, l.position.y, l.position.z);
        }
        if (l.type != scene::LightType::Point) {
            std::printf(" towards (%.3g, %.3g, %.3g)", l.direction.x, l.direction.y, l.direction.z);
        }
        if (l.type == scene::LightType::Spot) {
            std::printf(" cone %.3g-%.3g deg", glm::degrees(l.innerConeAngle), glm::degrees(l.outerConeAngle));
        }
        std::printf("\n");
    }
}

void printCameras(const scene::Scene& scene, const std::string& why) {
    std::printf("cameras    %zu\n", scene.cameras.size());
    if (!why.empty()) std::printf("  chosen: %s\n", why.c_str());
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const scene::Camera& c = scene.cameras[i];
        const glm::vec3 eye(c.worldFromCamera[3]);
        const glm::vec3 forward = -glm::vec3(c.worldFromCamera[2]);
        std::printf("  [%zu] %s at (%.4g, %.4g, %.4g) looking (%.3g, %.3g, %.3g) yfov %.4g deg\n", i,
                c.isDefault ? "(default)" : c.name.c_str(), eye.x, eye.y, eye.z, forward.x,
                forward.y, forward.z, glm::degrees(c.yfov));
    }
}

// The scene's own GPU buffers and textures.
void printSceneMemory(const scene::Scene& scene) {
    std::size_t vertexBytes = scene.vertexCount() * sizeof(scene::SceneVertex);
    std::size_t indexBytes = scene.triangleCount() * 3 * sizeof(std::uint32_t);
    std::size_t textureBytes = 0;
    for (const scene::Texture& t : scene.textures) {
        // RGBA8 with a full mip chain: 4/3 of the base level.
        textureBytes += std::size_t(t.width) * std::size_t(t.height) * 4 * 4 / 3;
    }
    std::printf("memory plan (GPU)\n");
    std::printf("  scene/vertices %10.2f MiB\n", mebibytes(vertexBytes));
    std::printf("  scene/indices  %10.2f MiB\n", mebibytes(indexBytes));
    std::printf("  scene/textures %10.2f MiB\n", mebibytes(textureBytes));
    std::printf("  total          %10.2f MiB\n", mebibytes(vertexBytes + indexBytes + textureBytes));
}

// The VPL mode's GPU memory at `settings`, for render's default image size (512 x 512 x
// render.supersample): the RSM views are drawn one after another into one set of textures.
void printVplMemory(const scene::Scene& scene, const std::vector<scene::Light>& lights,
        const Settings& settings) {
    const glm::ivec2 size = glm::ivec2(512) * settings.supersample;
    const int views = int(scene::lightViews(lights, scene.bounds, settings.vpl.rsmResolution).size());
    const std::vector<gl::MemoryItem> items = vpl::plannedVplMemory(settings.vpl, size);
    std::printf("  vpl      %d VPLs, RSMs of %d light view(s) at %d^2 drawn into one set, "
                "%dx%d G-buffer: %.2f MiB\n",
            settings.vpl.count, views, settings.vpl.rsmResolution, size.x, size.y,
            mebibytes(gl::totalBytes(items)));
    for (const gl::MemoryItem& item : items) {
        std::printf("    %-22s %10.3f MiB\n", item.name.c_str(), mebibytes(item.bytes));
    }
    if (settings.vpl.visibility == VPL_VISIBILITY_CASCADE) {
        if (settings.voxel.occupancyResolution > 0) {
            std::printf("    and the voxel occupancy vpl.visibility=cascade marches, %d^3 "
                        "(voxel.occupancy_resolution)\n",
                    settings.voxel.occupancyResolution);
        } else {
            std::printf("    and the voxel occupancy vpl.visibility=cascade marches\n");
        }
    } else if (settings.vpl.visibility == VPL_VISIBILITY_SVO) {
        std::printf("    and the sparse voxel octree, at most vpl.svo_budget_mb = %d MiB of nodes\n",
                settings.vpl.svoBudgetMb);
    }
}

// The BVH that atlas.visibility=bvh, the atlas' near field and vpl.visibility=bvh trace: the
// shadow rays' tree, built once for all of them.
void printGiRayMemory(const scene::Scene& scene, const std::vector<scene::Light>& lights,
        const Settings& settings) {
    std::vector<std::string> users;
    if (settings.atlas.visibility == ATLAS_VISIBILITY_BVH) users.push_back("atlas.visibility=bvh");
    if (settings.atlas.estimator == ATLAS_ESTIMATOR_AREA && settings.atlas.nearRays > 0) {
        users.push_back("the atlas' near field (atlas.near_rays)");
    }
    if (settings.vpl.visibility == VPL_VISIBILITY_BVH) users.push_back("vpl.visibility=bvh");
    if (users.empty()) return;
    std::string who = users[0];
    for (std::size_t i = 1; i < users.size(); ++i) {
        who += (i + 1 == users.size() ? " and " : ", ") + users[i];
    }
    Settings rays = settings;
    rays.shadow.enabled = true;
    rays.shadow.method = SHADOW_METHOD_BVH;
    const render::ShadowMethodReport tree = render::plannedShadowMethod(scene, lights, rays);
    const bool shared = settings.shadow.enabled && settings.shadow.method == SHADOW_METHOD_BVH;
    const bool small = tree.bytes < (std::size_t(1) << 20);
    std::printf("  GI rays: %s trace%s the %s, at most %.2f %s%s\n", who.c_str(),
            users.size() > 1 ? "" : "s", tree.structure.c_str(),
            small ? double(tree.bytes) / 1024.0 : mebibytes(tree.bytes), small ? "KiB" : "MiB",
            shared ? " (the shadows' own)" : "");
}

} // namespace

int runInfo(const Config& config) {
    scene::Scene scene;
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    scene::DefaultsReport defaults;
    if (!loadScene(config, scene, error, &defaults)) {
        std::fprintf(stderr, "voxatlas info: %s\n", error.c_str());
        return 2;
    }
    const double loadSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printContents(scene, loadSeconds);
    printLights(scene, defaults.lights);
    printCameras(scene, defaults.camera);
    printSceneMemory(scene);
    // The GI resources at the given settings (the adaptive plan unless render.plan=fixed or a
    // key it sizes was set), from the scene's first camera.
    const glm::vec3 eye = scene.cameras.empty() ? scene.bounds.center()
                                                : glm::vec3(scene.cameras.front().worldFromCamera[3]);
    const render::ResourcePlan plan = render::planResources(scene, scene.lights, config.settings, eye);
    std::printf("%s", render::describePlan(plan, config.plan.why).c_str());
    const Settings planned = render::applyPlan(config.settings, plan);
    const render::ShadowMethodReport shadows =
            render::plannedShadowMethod(scene, render::plannedLights(scene.lights, plan), planned);
    std::printf("  %s\n", render::describeShadowMethod(shadows).c_str());
    printGiRayMemory(scene, render::plannedLights(scene.lights, plan), planned);
    printVplMemory(scene, render::plannedLights(scene.lights, plan), planned);
    return 0;
}

} // namespace gi::app
