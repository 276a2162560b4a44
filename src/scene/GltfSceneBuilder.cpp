// SceneBuilder's driver and the checks that come before conversion (required extensions,
// samplers and texture references, perspective cameras, punctual lights), plus the world
// bounds of the placed instances.
#include "scene/GltfSceneBuilder.h"

#include "scene/GltfMessages.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace gi::scene::gltf {
namespace {

// World-space coordinates allowed (metres): squares of distances stay finite in float.
constexpr float kMaxCoordinate = 1e18f;

constexpr const char* kSupportedExtensions[] = {
        "KHR_lights_punctual",
        "KHR_materials_emissive_strength",
};

} // namespace

bool SceneBuilder::build(Scene& scene, std::string& error) {
    const bool ok = checkExtensions() && checkSamplersAndTextures() && checkCameras() &&
                    checkLights() && convertMaterials() && decodeTextures() &&
                    checkNodes() && instantiate() && computeBounds() && readAnimations();
    if (!ok) {
        error = mError;
        return false;
    }
    mScene.sourcePath = mName;
    scene = std::move(mScene);
    return true;
}

bool SceneBuilder::fail(const std::string& element, const std::string& what) {
    mError = mName + ": " + element + ": " + what;
    return false;
}

// `elementAndWhat` is already "<element>: <what>" (from the accessor reader).
bool SceneBuilder::failWith(const std::string& elementAndWhat) {
    mError = mName + ": " + elementAndWhat;
    return false;
}

void SceneBuilder::warn(const std::string& element, const std::string& what) {
    mWarnings.push_back(mName + ": " + element + ": " + what);
}

bool SceneBuilder::checkExtensions() {
    auto supported = [](const std::string& name) {
        return std::find_if(std::begin(kSupportedExtensions), std::end(kSupportedExtensions),
                       [&](const char* s) { return name == s; }) !=
               std::end(kSupportedExtensions);
    };
    for (const std::string& name : mModel.extensionsRequired) {
        if (!supported(name)) {
            return fail("extensionsRequired",
                    "extension '" + name + "' is not supported (supported: " +
                            "KHR_lights_punctual, KHR_materials_emissive_strength)");
        }
    }
    std::string ignored;
    for (const std::string& name : mModel.extensionsUsed) {
        if (!supported(name)) ignored += (ignored.empty() ? "" : ", ") + name;
    }
    if (!ignored.empty()) warn("extensionsUsed", "ignoring unsupported " + ignored);
    return true;
}

bool SceneBuilder::checkSamplersAndTextures() {
    for (std::size_t i = 0; i < mModel.samplers.size(); ++i) {
        const tinygltf::Sampler& sampler = mModel.samplers[i];
        for (const auto& [axis, wrap] : {std::pair{"wrapS", sampler.wrapS},
                     std::pair{"wrapT", sampler.wrapT}}) {
            if (wrap != TINYGLTF_TEXTURE_WRAP_REPEAT &&
                    wrap != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
                    wrap != TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) {
                return fail(indexed("samplers", long(i)),
                        std::string(axis) + " " + std::to_string(wrap) +
                                " is not CLAMP_TO_EDGE, MIRRORED_REPEAT or REPEAT");
            }
        }
    }
    for (std::size_t i = 0; i < mModel.textures.size(); ++i) {
        const tinygltf::Texture& texture = mModel.textures[i];
        if (texture.source < -1 || texture.source >= int(mModel.images.size())) {
            return fail(indexed("textures", long(i)),
                    doesNotExist("source", texture.source, mModel.images.size(), "images"));
        }
        if (texture.sampler < -1 || texture.sampler >= int(mModel.samplers.size())) {
            return fail(indexed("textures", long(i)),
                    doesNotExist("sampler", texture.sampler, mModel.samplers.size(),
                            "samplers"));
        }
    }
    return true;
}

bool SceneBuilder::checkCameras() {
    for (std::size_t i = 0; i < mModel.cameras.size(); ++i) {
        const tinygltf::Camera& camera = mModel.cameras[i];
        if (camera.type != "perspective") continue;
        const tinygltf::PerspectiveCamera& p = camera.perspective;
        const std::string element = indexed("cameras", long(i));
        if (!finite(p.yfov) || p.yfov <= 0.0 || p.yfov >= glm::pi<double>()) {
            return fail(element, "perspective.yfov " + std::to_string(p.yfov) +
                                         " is not in (0, pi)");
        }
        if (!finite(p.znear) || p.znear <= 0.0) {
            return fail(element, "perspective.znear " + std::to_string(p.znear) +
                                         " is not a positive number");
        }
        if (!finite(p.zfar) || (p.zfar != 0.0 && p.zfar <= p.znear)) {
            return fail(element, "perspective.zfar " + std::to_string(p.zfar) +
                                         " is not greater than znear");
        }
    }
    return true;
}

bool SceneBuilder::checkLights() {
    for (std::size_t i = 0; i < mModel.lights.size(); ++i) {
        const tinygltf::Light& light = mModel.lights[i];
        const std::string element = "KHR_lights_punctual." + indexed("lights", long(i));
        if (light.type != "point" && light.type != "spot" && light.type != "directional") {
            return fail(element, "type '" + light.type +
                                         "' is not point, spot or directional");
        }
        if (!(light.color.empty() || light.color.size() == 3) || !allFinite(light.color) ||
                std::any_of(light.color.begin(), light.color.end(),
                        [](double c) { return c < 0.0; })) {
            return fail(element, "color must be 3 finite numbers >= 0");
        }
        if (!finite(light.intensity) || light.intensity < 0.0) {
            return fail(element, "intensity " + std::to_string(light.intensity) +
                                         " is not a finite number >= 0");
        }
        if (!finite(light.range) || light.range < 0.0) {
            return fail(element, "range " + std::to_string(light.range) +
                                         " is not a finite number >= 0");
        }
        if (light.type == "spot") {
            const double inner = light.spot.innerConeAngle;
            const double outer = light.spot.outerConeAngle;
            if (!finite(inner) || !finite(outer) || inner < 0.0 || outer <= inner ||
                    outer > glm::half_pi<double>() + 1e-6) {
                return fail(element, "spot cone angles (inner " + std::to_string(inner) +
                                             ", outer " + std::to_string(outer) +
                                             ") must satisfy 0 <= inner < outer <= pi/2");
            }
        }
    }
    return true;
}

bool SceneBuilder::computeBounds() {
    for (const Instance& instance : mScene.instances) {
        const Primitive& primitive = mScene.primitives[std::size_t(instance.primitive)];
        for (const glm::vec3& p : primitive.positions) {
            const glm::vec3 world = glm::vec3(instance.worldFromLocal * glm::vec4(p, 1.0f));
            if (!std::isfinite(world.x) || !std::isfinite(world.y) ||
                    !std::isfinite(world.z)) {
                return fail(indexed("nodes", instance.node),
                        "a vertex placed by this node is not finite in world space");
            }
            mScene.bounds.extend(world);
        }
        // Passes and addDefaults square distances and sum extents in single precision.
        if (glm::any(glm::greaterThan(glm::max(-mScene.bounds.min, mScene.bounds.max),
                    glm::vec3(kMaxCoordinate)))) {
            return fail(indexed("nodes", instance.node),
                    "places vertices beyond +-1e18 m, too far for single precision maths");
        }
    }
    return true;
}

} // namespace gi::scene::gltf
