// The reference renderer's scene: world-space triangles of all instances with the shading
// attributes a hit needs, and the Embree scene over them (geometry 0 opaque triangles,
// geometry 1 alpha-masked ones, whose filter lets rays pass through cut-out texels).
#pragma once

#include "reference/SamplingMath.h"
#include "reference/TextureSampling.h"
#include "scene/Scene.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gi::reference {

// Ray origins move off a surface along its geometric normal by this fraction of the largest
// coordinate magnitude M of the triangle's corners (which bounds the hit point's). The
// interpolated hit point and Embree's single-precision plane test both err by a few ulps of M,
// so 2^-17 M = 64 ulps keeps every continuation ray off its own triangle, while moving the
// origin so little (8e-6 M) that it biases irradiance by far less than the test tolerances.
constexpr float kRelativeOffset = 1.0f / 131072.0f;

struct ShadingMaterial {
    glm::vec4 baseColorFactor{1.0f};
    const scene::Texture* baseColorTexture = nullptr;
    int baseColorTexCoord = 0;
    glm::vec3 emissiveFactor{0.0f};
    const scene::Texture* emissiveTexture = nullptr;
    int emissiveTexCoord = 0;
    bool mask = false;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;   // emits from both sides (DESIGN: front side otherwise)
    float metallic = 0.0f;      // glTF metallic-roughness (GltfBrdf.h), glossy model only
    float roughness = 1.0f;
};

struct EmbreeState;

// What shading needs per triangle, precomputed so that a hit costs no cross products.
struct TriangleInfo {
    glm::vec3 normal{0.0f};       // unit geometric normal (world space), 0 when degenerate
    float offset = 0.0f;          // ray-origin offset: kRelativeOffset x largest |coordinate|
    std::uint32_t material = 0;   // index into EmbreeState::materials
    std::uint32_t flags = 0;      // kSmoothNormals | kVertexColors
};
constexpr std::uint32_t kSmoothNormals = 1;   // vertex normals differ from the geometric one
constexpr std::uint32_t kVertexColors = 2;    // some corner has COLOR_0 other than white

// User data of the alpha-masked Embree geometry.
struct FilterData {
    const EmbreeState* state = nullptr;
    std::uint32_t firstTriangle = 0;
};

// Where one scene instance's triangles are in EmbreeState::triangles: [first, first + count),
// in the primitive's order (an instance is wholly opaque or wholly masked).
struct TriangleRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};

// World-space triangles of all instances with their shading attributes, and the Embree scene
// over them: geometry 0 holds opaque triangles, geometry 1 alpha-masked ones (with filters).
struct EmbreeState {
    std::vector<glm::vec3> positions;     // world space
    std::vector<glm::vec3> normals;       // world space, unit
    std::vector<glm::vec2> texcoords[2];
    std::vector<glm::vec4> colors;        // linear RGBA, white when the primitive has none
    std::vector<glm::uvec3> triangles;    // global vertex indices; opaque first, then masked
    std::vector<TriangleInfo> triangleInfo;        // per triangle, same order
    std::vector<ShadingMaterial> materials;        // scene materials + default white last
    std::uint32_t firstTriangle[2] = {0, 0};       // per Embree geometry id
    std::vector<TriangleRange> instanceTriangles;  // per scene instance
    FilterData maskFilter;

    RTCDevice device = nullptr;
    RTCScene rtcScene = nullptr;
    std::string deviceError;
    double buildSeconds = 0.0;

    ~EmbreeState() {
        if (rtcScene) rtcReleaseScene(rtcScene);
        if (device) rtcReleaseDevice(device);
    }

    glm::vec2 texcoord(std::uint32_t triangle, int set, float u, float v) const {
        const std::vector<glm::vec2>& uv = texcoords[set == 1 ? 1 : 0];
        const glm::uvec3 t = triangles[triangle];
        return (1.0f - u - v) * uv[t.x] + u * uv[t.y] + v * uv[t.z];
    }

    glm::vec4 baseColor(std::uint32_t triangle, float u, float v) const {
        const TriangleInfo& info = triangleInfo[triangle];
        const ShadingMaterial& m = materials[info.material];
        glm::vec4 color = m.baseColorFactor;
        if (info.flags & kVertexColors) {
            const glm::uvec3 t = triangles[triangle];
            color *= (1.0f - u - v) * colors[t.x] + u * colors[t.y] + v * colors[t.z];
        }
        if (m.baseColorTexture) {
            color *= sampleTexture(*m.baseColorTexture,
                    texcoord(triangle, m.baseColorTexCoord, u, v));
        }
        return color;
    }

    // Emitted radiance at barycentrics (u, v), on whichever side emits (see doubleSided).
    glm::vec3 emission(std::uint32_t triangle, float u, float v) const {
        const ShadingMaterial& m = materials[triangleInfo[triangle].material];
        glm::vec3 le = m.emissiveFactor;
        if (m.emissiveTexture && maxComponent(le) > 0.0f) {
            le *= glm::vec3(sampleTexture(*m.emissiveTexture,
                    texcoord(triangle, m.emissiveTexCoord, u, v)));
        }
        return le;
    }

    // Whether the triangle emits towards a viewer in direction `towards` from it (unit):
    // front side (counter-clockwise) only, unless the material is double-sided.
    bool emitsTowards(std::uint32_t triangle, const glm::vec3& towards) const {
        const TriangleInfo& info = triangleInfo[triangle];
        return materials[info.material].doubleSided || glm::dot(info.normal, towards) > 0.0f;
    }

    bool cutOut(std::uint32_t triangle, float u, float v) const {
        const ShadingMaterial& m = materials[triangleInfo[triangle].material];
        return m.mask && baseColor(triangle, u, v).a < m.alphaCutoff;
    }
};

// Builds the state for `scene`; null, with `error` set, when Embree fails.
std::unique_ptr<EmbreeState> buildEmbreeState(const scene::Scene& scene, std::string& error);

// A ray from `origin` along `direction` over [tnear, tfar], its hit not yet found.
[[nodiscard]] RTCRayHit makeRayHit(const glm::vec3& origin, const glm::vec3& direction,
        float tnear, float tfar);

} // namespace gi::reference
