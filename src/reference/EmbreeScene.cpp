#include "reference/EmbreeScene.h"

#include "reference/SamplingMath.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gi::reference {
namespace {

// Embree intersection and occlusion filter of the masked geometry: rejects hits where the
// material's alpha (factor x texture x COLOR_0, as the raster passes compute it) is below the
// cutoff, so rays continue through cut-out texels.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
    const auto* data = static_cast<const FilterData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const std::uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (data->state->cutOut(data->firstTriangle + prim, u, v)) args->valid[i] = 0;
    }
}

void embreeErrorCallback(void* user, RTCError, const char* message) {
    auto* text = static_cast<std::string*>(user);
    if (text->empty() && message) *text = message;
}

// Shading materials of the scene's materials, then a default white one.
void copyMaterials(const scene::Scene& scene, EmbreeState& state) {
    for (const scene::Material& material : scene.materials) {
        ShadingMaterial m;
        m.baseColorFactor = material.baseColorFactor;
        auto texture = [&](int index) -> const scene::Texture* {
            return index >= 0 && std::size_t(index) < scene.textures.size()
                           ? &scene.textures[std::size_t(index)]
                           : nullptr;
        };
        m.baseColorTexture = texture(material.baseColorTexture);
        m.baseColorTexCoord = material.baseColorTexCoord;
        m.emissiveFactor = material.emissiveFactor;
        m.emissiveTexture = texture(material.emissiveTexture);
        m.emissiveTexCoord = material.emissiveTexCoord;
        m.mask = material.alphaMode == scene::AlphaMode::Mask;
        m.alphaCutoff = material.alphaCutoff;
        m.doubleSided = material.doubleSided;
        m.metallic = material.metallicFactor;
        m.roughness = material.roughnessFactor;
        state.materials.push_back(m);
    }
    state.materials.push_back(ShadingMaterial{});
}

// World-space vertices of every instance and its triangles, opaque ones first; `material`
// receives each triangle's material in the same order.
void appendInstances(const scene::Scene& scene, EmbreeState& state,
        std::vector<std::uint32_t>& material) {
    const auto defaultMaterial = std::uint32_t(state.materials.size() - 1);
    std::vector<glm::uvec3> masked;
    std::vector<std::uint32_t> maskedMaterial;
    std::vector<bool> instanceMasked;
    for (const scene::Instance& instance : scene.instances) {
        const scene::Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        const auto base = std::uint32_t(state.positions.size());
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(instance.worldFromLocal));
        const std::size_t count = primitive.positions.size();
        for (std::size_t i = 0; i < count; ++i) {
            state.positions.push_back(
                    glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[i], 1.0f)));
            glm::vec3 n = i < primitive.normals.size() ? normalMatrix * primitive.normals[i]
                                                       : glm::vec3(0.0f);
            const float length = glm::length(n);
            state.normals.push_back(length > 0.0f && std::isfinite(length) ? n / length
                                                                            : glm::vec3(0.0f));
            state.texcoords[0].push_back(
                    i < primitive.texcoords0.size() ? primitive.texcoords0[i] : glm::vec2(0.0f));
            state.texcoords[1].push_back(
                    i < primitive.texcoords1.size() ? primitive.texcoords1[i] : glm::vec2(0.0f));
            state.colors.push_back(i < primitive.colors.size() ? primitive.colors[i]
                                                               : glm::vec4(1.0f));
        }
        const std::uint32_t primitiveMaterial =
                primitive.material >= 0 && std::size_t(primitive.material) < scene.materials.size()
                        ? std::uint32_t(primitive.material)
                        : defaultMaterial;
        const bool isMasked = state.materials[primitiveMaterial].mask;
        instanceMasked.push_back(isMasked);
        state.instanceTriangles.push_back({std::uint32_t(isMasked ? masked.size()
                                                                  : state.triangles.size()),
                std::uint32_t(primitive.indices.size() / 3)});
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            const glm::uvec3 triangle(base + primitive.indices[t], base + primitive.indices[t + 1],
                    base + primitive.indices[t + 2]);
            if (isMasked) {
                masked.push_back(triangle);
                maskedMaterial.push_back(primitiveMaterial);
            } else {
                state.triangles.push_back(triangle);
                material.push_back(primitiveMaterial);
            }
        }
    }
    state.firstTriangle[0] = 0;
    state.firstTriangle[1] = std::uint32_t(state.triangles.size());
    state.triangles.insert(state.triangles.end(), masked.begin(), masked.end());
    material.insert(material.end(), maskedMaterial.begin(), maskedMaterial.end());
    for (std::size_t i = 0; i < instanceMasked.size(); ++i) {
        if (instanceMasked[i]) state.instanceTriangles[i].first += state.firstTriangle[1];
    }
}

void computeTriangleInfo(EmbreeState& state, const std::vector<std::uint32_t>& material) {
    state.triangleInfo.resize(state.triangles.size());
    for (std::size_t i = 0; i < state.triangles.size(); ++i) {
        const glm::uvec3 t = state.triangles[i];
        const glm::vec3& p0 = state.positions[t.x];
        const glm::vec3& p1 = state.positions[t.y];
        const glm::vec3& p2 = state.positions[t.z];
        TriangleInfo& info = state.triangleInfo[i];
        info.material = material[i];
        const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
        const float length = glm::length(n);
        info.normal = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f);
        info.offset = std::max(kRelativeOffset * std::max({maxAbs(p0), maxAbs(p1), maxAbs(p2)}),
                std::numeric_limits<float>::min());
        for (const std::uint32_t vertex : {t.x, t.y, t.z}) {
            // Normals within ~0.01 degrees of the face normal (either side) shade as flat.
            if (std::abs(glm::dot(state.normals[vertex], info.normal)) < 0.99999999f) {
                info.flags |= kSmoothNormals;
            }
            if (state.colors[vertex] != glm::vec4(1.0f)) info.flags |= kVertexColors;
        }
    }
}

void fillState(const scene::Scene& scene, EmbreeState& state) {
    copyMaterials(scene, state);
    std::vector<std::uint32_t> material;
    appendInstances(scene, state, material);
    computeTriangleInfo(state, material);
}

// Adds triangles [first, first + count) as one Embree geometry; returns false on an Embree error.
bool addGeometry(EmbreeState& state, std::uint32_t first, std::uint32_t count, bool masked,
        FilterData* filterData) {
    RTCGeometry geometry = rtcNewGeometry(state.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) return false;
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX,
            0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), state.positions.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(geometry,
            RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), count));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        return false;
    }
    for (std::size_t i = 0; i < state.positions.size(); ++i) {
        vertices[3 * i] = state.positions[i].x;
        vertices[3 * i + 1] = state.positions[i].y;
        vertices[3 * i + 2] = state.positions[i].z;
    }
    for (std::uint32_t t = 0; t < count; ++t) {
        const glm::uvec3& triangle = state.triangles[first + t];
        indices[3 * t] = triangle.x;
        indices[3 * t + 1] = triangle.y;
        indices[3 * t + 2] = triangle.z;
    }
    if (masked) {
        filterData->state = &state;
        filterData->firstTriangle = first;
        rtcSetGeometryUserData(geometry, filterData);
        rtcSetGeometryIntersectFilterFunction(geometry, alphaMaskFilter);
        rtcSetGeometryOccludedFilterFunction(geometry, alphaMaskFilter);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(state.rtcScene, geometry, masked ? 1u : 0u);
    rtcReleaseGeometry(geometry);
    return true;
}

} // namespace

std::unique_ptr<EmbreeState> buildEmbreeState(const scene::Scene& scene, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    auto state = std::make_unique<EmbreeState>();
    fillState(scene, *state);
    state->device = rtcNewDevice(nullptr);
    if (!state->device) {
        error = "cannot create the Embree device (error " +
                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")";
        return nullptr;
    }
    rtcSetDeviceErrorFunction(state->device, embreeErrorCallback, &state->deviceError);
    state->rtcScene = rtcNewScene(state->device);
    // ROBUST keeps shared edges watertight, so paths never leak out of closed rooms.
    rtcSetSceneFlags(state->rtcScene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(state->rtcScene, RTC_BUILD_QUALITY_HIGH);
    const std::uint32_t opaque = state->firstTriangle[1];
    const auto masked = std::uint32_t(state->triangles.size()) - opaque;
    bool ok = true;
    if (opaque > 0) ok = ok && addGeometry(*state, 0, opaque, false, nullptr);
    if (masked > 0) ok = ok && addGeometry(*state, opaque, masked, true, &state->maskFilter);
    rtcCommitScene(state->rtcScene);
    if (!ok || !state->deviceError.empty()) {
        error = "Embree scene build failed: " +
                 (state->deviceError.empty() ? std::string("out of memory") : state->deviceError);
        return nullptr;
    }
    state->buildSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return state;
}

RTCRayHit makeRayHit(const glm::vec3& origin, const glm::vec3& direction, float tnear,
        float tfar) {
    RTCRayHit rayHit{};
    rayHit.ray.org_x = origin.x;
    rayHit.ray.org_y = origin.y;
    rayHit.ray.org_z = origin.z;
    rayHit.ray.dir_x = direction.x;
    rayHit.ray.dir_y = direction.y;
    rayHit.ray.dir_z = direction.z;
    rayHit.ray.tnear = tnear;
    rayHit.ray.tfar = tfar;
    rayHit.ray.mask = 0xFFFFFFFFu;
    rayHit.ray.time = 0.0f;
    rayHit.ray.flags = 0;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayHit;
}

} // namespace gi::reference
