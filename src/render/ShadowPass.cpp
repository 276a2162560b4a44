#include "render/ShadowPass.h"

#include "gl/Shared.h"
#include "scene/SunWindow.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gi::render {
namespace {

// Farthest the scene reaches from a point: the far plane of maps centred there.
float farthestFrom(const glm::vec3& p, const scene::Aabb& bounds) {
    if (bounds.empty()) return 1.0f;
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x,
                (i & 2) ? bounds.max.y : bounds.min.y, (i & 4) ? bounds.max.z : bounds.min.z);
        farthest = std::max(farthest, glm::length(corner - p));
    }
    return std::max(farthest * 1.01f, 1e-5f);
}

glm::vec3 anyPerpendicularUp(const glm::vec3& direction) {
    return std::abs(direction.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Texels per side of the 2D maps (spot and directional lights share one array) and of the
// cube faces. A directional light's map spans the whole scene, so it has
// shadow.sun_resolution texels a side where the others have shadow.resolution; a spot light
// in the same scene shares its array and its finer texels. Kinds no light uses get 1x1
// maps: the shader's samplers must always be complete.
struct MapResolutions {
    int flat = 1, cube = 1;
};

MapResolutions mapResolutions(const std::vector<scene::Light>& lights, const ShadowSettings& settings) {
    MapResolutions res;
    for (const scene::Light& light : lights) {
        if (!settings.enabled) break;
        switch (light.type) {
        case scene::LightType::Point:
        case scene::LightType::Area: res.cube = settings.resolution; break;
        case scene::LightType::Spot: res.flat = std::max(res.flat, settings.resolution); break;
        case scene::LightType::Directional:
            res.flat = std::max({res.flat, settings.resolution, settings.sunResolution});
            break;
        case scene::LightType::Sky: break;   // unshadowed: cones see it
        }
    }
    return res;
}

gl::Texture createShadowArray(GLenum target, int resolution, int layers, const char* label) {
    gl::Texture texture = target == GL_TEXTURE_CUBE_MAP_ARRAY
            ? gl::createTextureCubeArray(GL_DEPTH_COMPONENT32F, resolution, std::max(layers, 1), label)
            : gl::createTexture2DArray(GL_DEPTH_COMPONENT32F, {resolution, resolution},
                      std::max(layers, 1), label);
    glTextureParameteri(texture.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(texture.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

} // namespace

bool ShadowPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    mProgram = shaders.build({"render/shadow",
            {{GL_VERTEX_SHADER, "render/shadow.vert"}, {GL_FRAGMENT_SHADER, "render/shadow.frag"}},
            {}}, error);
    mFramebuffer = gl::createFramebuffer("render/shadow");
    return bool(mProgram);
}

void ShadowPass::setLights(const std::vector<scene::Light>& lights, const scene::Aabb& bounds,
        const ShadowSettings& settings) {
    mViews.clear();
    std::vector<shader::GpuShadow> table(std::max<std::size_t>(lights.size(), 1));
    int layers2D = 0, layersCube = 0;
    const MapResolutions res = mapResolutions(lights, settings);
    for (std::size_t i = 0; i < lights.size() && settings.enabled; ++i) {
        const scene::Light& light = lights[i];
        shader::GpuShadow& s = table[i];
        s.bias = glm::vec4(settings.normalOffset, settings.pcfRadius, 0.0f, 0.0f);
        if (light.type == scene::LightType::Sky) continue;   // unshadowed here: cones see it
        // An area light is shadowed as if all of it shone from its centre.
        if (light.type == scene::LightType::Point || light.type == scene::LightType::Area) {
            const float far = farthestFrom(light.position, bounds);
            const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, far * 1e-4f, far);
            // Cube-map face order and up vectors of the GL specification (table 8.19).
            static const std::array<std::pair<glm::vec3, glm::vec3>, 6> faces = {{
                    {{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                    {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}}};
            for (int face = 0; face < 6; ++face) {
                const glm::mat4 view = glm::lookAt(light.position,
                        light.position + faces[std::size_t(face)].first, faces[std::size_t(face)].second);
                mViews.push_back({projection * view, glm::vec4(light.position, far),
                        layersCube * 6 + face, true, light.type == scene::LightType::Area});
            }
            s.params = glm::vec4(SHADOW_CUBE, float(layersCube), far, 2.0f / float(res.cube));
            ++layersCube;
        } else if (light.type == scene::LightType::Spot) {
            const float far = farthestFrom(light.position, bounds);
            const float fov = std::min(2.0f * light.outerConeAngle + glm::radians(2.0f), glm::radians(170.0f));
            const glm::mat4 projection = glm::perspective(fov, 1.0f, far * 1e-4f, far);
            const glm::mat4 view = glm::lookAt(light.position, light.position + light.direction,
                    anyPerpendicularUp(light.direction));
            s.worldToShadow = projection * view;
            mViews.push_back({s.worldToShadow, glm::vec4(0.0f), layers2D, false});
            s.params = glm::vec4(SHADOW_2D, float(layers2D), far,
                    2.0f * std::tan(0.5f * fov) / float(res.flat));
            ++layers2D;
        } else {
            // The window over the scene box's outline (scene/SunWindow.h); its longer side
            // sets the texel the normal offset is measured in.
            const scene::SunWindow window = scene::sunWindow(light.direction, bounds);
            s.worldToShadow = window.projection * window.view;
            mViews.push_back({s.worldToShadow, glm::vec4(0.0f), layers2D, false});
            s.params = glm::vec4(SHADOW_2D, float(layers2D), window.depth,
                    std::max(window.size.x, window.size.y) / float(res.flat));
            s.bias.z = 1.0f;
            ++layers2D;
        }
    }
    if (!mMaps2D || layers2D != mLayers2D || layersCube != mLayersCube || res.flat != mResolution2D ||
            res.cube != mResolutionCube) {
        mMaps2D = createShadowArray(GL_TEXTURE_2D_ARRAY, res.flat, layers2D, "render/shadow/maps_2d");
        mMapsCube = createShadowArray(GL_TEXTURE_CUBE_MAP_ARRAY, res.cube, layersCube, "render/shadow/maps_cube");
    }
    mLayers2D = layers2D;
    mLayersCube = layersCube;
    mResolution2D = res.flat;
    mResolutionCube = res.cube;
    mShadowTable = gl::createBuffer(table.size() * sizeof(shader::GpuShadow), table.data(), 0,
            "render/shadow/table");
    mDirty = true;
}

void ShadowPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    const scene::GpuScene& scene = in.scene;
    if (!mDirty) return;
    mDirty = false;
    if (mViews.empty()) return;
    gl::GpuScope scope(profiler, "render/shadow");
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glNamedFramebufferDrawBuffer(mFramebuffer.id(), GL_NONE);
    glNamedFramebufferReadBuffer(mFramebuffer.id(), GL_NONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mProgram.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, scene.materialBuffer().id());
    for (const View& view : mViews) {
        glNamedFramebufferTextureLayer(mFramebuffer.id(), GL_DEPTH_ATTACHMENT,
                view.cube ? mMapsCube.id() : mMaps2D.id(), 0, view.layer);
        const int size = view.cube ? mResolutionCube : mResolution2D;
        glViewport(0, 0, size, size);
        const float clearDepth = 1.0f;
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &clearDepth);
        // Slope-scaled offset for hardware depth; cube faces write their own depth and are
        // biased by the normal offset at lookup instead.
        if (view.cube) glDisable(GL_POLYGON_OFFSET_FILL);
        else {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(2.0f, 4.0f);
        }
        glProgramUniformMatrix4fv(mProgram.id(), LOC_SHADOW_VIEW_PROJECTION, 1, GL_FALSE,
                &view.viewProjection[0][0]);
        glProgramUniform4fv(mProgram.id(), LOC_SHADOW_LIGHT_POSITION, 1, &view.lightPositionAndFar[0]);
        // Both faces cast: single-sided walls seen from behind still block light.
        scene.drawAll(mProgram.id(), false, nullptr,
                view.areaLight ? scene::GpuScene::DrawSet::NotEmittingLight : scene::GpuScene::DrawSet::All);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowPass::bind() const {
    glBindTextureUnit(BIND_TEX_SHADOW_2D, mMaps2D.id());
    glBindTextureUnit(BIND_TEX_SHADOW_CUBE, mMapsCube.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SHADOWS, mShadowTable.id());
}

std::string ShadowPass::resolutionText(const std::vector<scene::Light>& lights,
        const ShadowSettings& settings) {
    const bool anySun = std::any_of(lights.begin(), lights.end(), [](const scene::Light& l) {
        return l.type == scene::LightType::Directional;
    });
    return "shadow.resolution " + std::to_string(settings.resolution) +
            (anySun ? ", suns at shadow.sun_resolution " + std::to_string(settings.sunResolution)
                    : std::string());
}

std::vector<gl::MemoryItem> ShadowPass::memoryFor(const std::vector<scene::Light>& lights,
        const ShadowSettings& settings) {
    int layers2D = 0, layersCube = 0;
    for (const scene::Light& light : lights) {
        if (!settings.enabled) break;
        if (light.type == scene::LightType::Sky) continue;
        (light.type == scene::LightType::Point || light.type == scene::LightType::Area ? layersCube
                                                                                        : layers2D) += 1;
    }
    const MapResolutions res = mapResolutions(lights, settings);
    return {{"render/shadow/maps_2d",
                    gl::textureBytes(GL_DEPTH_COMPONENT32F, {res.flat, res.flat, std::max(layers2D, 1)}, 1)},
            {"render/shadow/maps_cube",
                    gl::textureBytes(GL_DEPTH_COMPONENT32F, {res.cube, res.cube, 6 * std::max(layersCube, 1)}, 1)}};
}

int ShadowPass::mapKinds() const {
    return (mLayers2D > 0 ? 1 << SHADOW_2D : 0) | (mLayersCube > 0 ? 1 << SHADOW_CUBE : 0);
}

} // namespace gi::render
