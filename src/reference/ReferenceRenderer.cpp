#include "reference/ReferenceRenderer.h"
#include "core/Colour.h"

#include "reference/OwenSobol.h"
#include "reference/Pcg32.h"

#include <embree3/rtcore.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace gi::reference {

namespace {

constexpr int kTileSize = 16;
// Ray origins move off a surface along its geometric normal by this fraction of the largest
// coordinate magnitude M of the triangle's corners (which bounds the hit point's). The
// interpolated hit point and Embree's single-precision plane test both err by a few ulps of M,
// so 2^-17 M = 64 ulps keeps every continuation ray off its own triangle, while moving the
// origin so little (8e-6 M) that it biases irradiance by far less than the test tolerances.
constexpr float kRelativeOffset = 1.0f / 131072.0f;
// A shadow ray towards a point or spot light stops this fraction short of the light, so a
// light placed exactly on a surface is not shadowed by it.
constexpr float kShadowRayShortening = 1e-4f;

enum GlWrap : int { kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648 };

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = core::srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

// Folds a texture coordinate into [0, 1] by the sampler's wrap mode (for REPEAT, [0, 1)).
float wrapCoordinate(float u, int wrap) {
    if (!std::isfinite(u)) return 0.0f;
    if (wrap == kClampToEdge) return std::clamp(u, 0.0f, 1.0f);
    if (wrap == kMirroredRepeat) {
        const float m = u - 2.0f * std::floor(0.5f * u);
        return m > 1.0f ? 2.0f - m : m;
    }
    return u - std::floor(u);
}

int wrapIndex(int i, int size, int wrap) {
    if (wrap == kRepeat) return i < 0 ? i + size : (i >= size ? i - size : i);
    return std::clamp(i, 0, size - 1);   // clamp; mirrored repeat reflects onto the edge texel
}

// Bilinear lookup with the texture's wrap modes; colour channels of sRGB textures are decoded
// to linear before filtering (as an SRGB8_ALPHA8 texture on the GPU), alpha is linear.
glm::vec4 sampleTexture(const scene::Texture& texture, glm::vec2 uv) {
    if (texture.width <= 0 || texture.height <= 0 ||
            texture.rgba8.size() < std::size_t(texture.width) * std::size_t(texture.height) * 4) {
        return glm::vec4(1.0f);
    }
    const float x = wrapCoordinate(uv.x, texture.wrapS) * float(texture.width) - 0.5f;
    const float y = wrapCoordinate(uv.y, texture.wrapT) * float(texture.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = int(fx), y0 = int(fy);
    const int xs[2] = {wrapIndex(x0, texture.width, texture.wrapS),
            wrapIndex(x0 + 1, texture.width, texture.wrapS)};
    const int ys[2] = {wrapIndex(y0, texture.height, texture.wrapT),
            wrapIndex(y0 + 1, texture.height, texture.wrapT)};
    const float wx[2] = {1.0f - tx, tx};
    const float wy[2] = {1.0f - ty, ty};
    const std::array<float, 256>& table = srgbTable();
    glm::vec4 result(0.0f);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const std::uint8_t* texel = texture.rgba8.data() +
                    (std::size_t(ys[j]) * std::size_t(texture.width) + std::size_t(xs[i])) * 4;
            glm::vec4 value;
            if (texture.srgb) {
                value = {table[texel[0]], table[texel[1]], table[texel[2]], 0.0f};
            } else {
                value = {float(texel[0]) / 255.0f, float(texel[1]) / 255.0f,
                        float(texel[2]) / 255.0f, 0.0f};
            }
            value.a = float(texel[3]) / 255.0f;
            result += (wx[i] * wy[j]) * value;
        }
    }
    return result;
}

float maxAbs(const glm::vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

float maxComponent(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

// Orthonormal basis around a unit vector (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017).
void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction about n (Malley's method, PBRT 3rd ed. 13.6.3): pdf = cos/pi.
glm::vec3 sampleCosineHemisphere(const glm::vec3& n, float u1, float u2) {
    const float r = std::sqrt(u1);
    const float phi = glm::two_pi<float>() * u2;
    glm::vec3 t, b;
    orthonormalBasis(n, t, b);
    const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + z * n);
}

struct ShadingMaterial {
    glm::vec4 baseColorFactor{1.0f};
    const scene::Texture* baseColorTexture = nullptr;
    int baseColorTexCoord = 0;
    glm::vec3 emissiveFactor{0.0f};
    const scene::Texture* emissiveTexture = nullptr;
    int emissiveTexCoord = 0;
    bool mask = false;
    float alphaCutoff = 0.5f;
};

struct Surface {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};   // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};     // unit, on the side the ray came from
    glm::vec3 albedo{0.0f};
    glm::vec3 emission{0.0f};
    float offset = 0.0f;               // metres to move ray origins off the surface
};

struct PathSample {
    glm::vec3 direct{0.0f};
    glm::vec3 indirect{0.0f};
    bool hit = false;
};

} // namespace

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

    bool cutOut(std::uint32_t triangle, float u, float v) const {
        const ShadingMaterial& m = materials[triangleInfo[triangle].material];
        return m.mask && baseColor(triangle, u, v).a < m.alphaCutoff;
    }
};

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

void fillState(const scene::Scene& scene, EmbreeState& state) {
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
        state.materials.push_back(m);
    }
    const auto defaultMaterial = std::uint32_t(state.materials.size());
    state.materials.push_back(ShadingMaterial{});

    std::vector<glm::uvec3> masked;
    std::vector<std::uint32_t> material;
    std::vector<std::uint32_t> maskedMaterial;
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

// False for lights that emit nothing or whose numbers are not finite (never NaN pixels).
bool usableLight(const scene::Light& light, const glm::vec3& radiant) {
    const bool finite = std::isfinite(radiant.x) && std::isfinite(radiant.y) &&
                        std::isfinite(radiant.z) && std::isfinite(light.position.x) &&
                        std::isfinite(light.position.y) && std::isfinite(light.position.z);
    return finite && maxComponent(radiant) > 0.0f;
}

// Unit vector along v; false when v is zero or not finite (a light without a direction).
bool normalized(const glm::vec3& v, glm::vec3& unit) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return false;
    unit = v / length;
    return true;
}

// Direction density (per steradian) with which lightSubpathDirection samples a light's
// emission: uniform over the sphere (point) or over the outer cone (spot). 0 for lights whose
// emission cannot be sampled (directional, or a spot with a zero-width cone): those are
// reached by next-event estimation alone.
float emissionPdf(const scene::Light& light) {
    glm::vec3 axis;
    if (light.type == scene::LightType::Point) return 1.0f / (4.0f * glm::pi<float>());
    if (light.type == scene::LightType::Spot && normalized(light.direction, axis)) {
        const float solidAngle = glm::two_pi<float>() *
                (1.0f - std::cos(std::clamp(light.outerConeAngle, 0.0f, glm::pi<float>())));
        return solidAngle > 1e-6f ? 1.0f / solidAngle : 0.0f;
    }
    return 0.0f;
}

glm::vec3 lightSubpathDirection(const scene::Light& light, float u1, float u2) {
    float cosTheta = 1.0f - 2.0f * u1;
    glm::vec3 axis(0.0f, 0.0f, 1.0f);
    if (light.type == scene::LightType::Spot) {
        const float cosOuter = std::cos(std::clamp(light.outerConeAngle, 0.0f, glm::pi<float>()));
        cosTheta = 1.0f - u1 * (1.0f - cosOuter);
        axis = glm::normalize(light.direction);   // non-zero: emissionPdf > 0
    }
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = glm::two_pi<float>() * u2;
    glm::vec3 t, b;
    orthonormalBasis(axis, t, b);
    return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b +
                          cosTheta * axis);
}

// How a punctual light reaches point p: wi (unit, towards the light), the shadow-ray length,
// and E / (colour x intensity x cos(theta)) per DESIGN.md: 1/d^2 (point), s^2/d^2 (spot),
// 1 (directional). False when the light cannot reach p (on it, or outside a spot's cone).
bool lightGeometry(const scene::Light& light, const glm::vec3& p, glm::vec3& wi,
        float& distance, float& factor) {
    glm::vec3 axis(0.0f);
    if (light.type != scene::LightType::Point && !normalized(light.direction, axis)) return false;
    if (light.type == scene::LightType::Directional) {
        wi = -axis;
        distance = std::numeric_limits<float>::infinity();
        factor = 1.0f;
        return true;
    }
    const glm::vec3 toLight = light.position - p;
    const float distance2 = glm::dot(toLight, toLight);
    if (!(distance2 > 0.0f) || !std::isfinite(distance2)) return false;
    distance = std::sqrt(distance2);
    wi = toLight / distance;
    factor = 1.0f / distance2;
    if (light.type == scene::LightType::Spot) {
        const float cosAlpha = glm::dot(axis, -wi);
        const float cosOuter = std::cos(light.outerConeAngle);
        const float cosInner = std::cos(light.innerConeAngle);
        float s = 0.0f;
        if (cosInner > cosOuter) {
            s = std::clamp((cosAlpha - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
        } else {
            s = cosAlpha >= cosOuter ? 1.0f : 0.0f;
        }
        factor *= s * s;
    }
    return factor > 0.0f && std::isfinite(factor);
}

// The first surface a light's emission hits (a light subpath of one vertex), with what the
// connection strategy needs: its outgoing radiance due to the light and its area density.
struct LightVertex {
    Surface surface;
    glm::vec3 radiance{0.0f};   // rho/pi x colour x intensity x E-factor x cos at the vertex
    float pdfArea = 0.0f;       // emissionPdf x |cos_g| / d^2
    bool valid = false;
};

// Everything one render() call shares between its worker threads.
//
// Light transport: a path x0 (camera hit), x1, ... of length up to `bounces` bounces. Direct
// light at x0 is next-event estimation (NEE). Light reaching x_j (j >= 1) from a point or spot
// light, i.e. the paths x_(j-1) -> x_j -> light, is estimated with two strategies combined by
// multiple importance sampling with the balance heuristic (Veach 1997, ch. 9; PBRT 3rd ed.
// 14.3 and 16.3): (A) x_j found by cosine sampling at x_(j-1), then NEE at x_j; (B) x_j found
// as the first hit of a ray sampled from the light's emission (a light vertex), then connected
// to x_(j-1) with a visibility ray. (A) alone is noisy where a light sits close to a surface
// (the Cornell box's light is 1 cm under the ceiling: a hot spot a bounce ray rarely finds);
// (B) handles that, while (A) handles nearby geometry, where (B)'s 1/d^2 diverges. Both
// weights use area densities at x_j: pA = cos_s(x_(j-1))/pi |cos_g(x_j)| / d^2 and
// pB = emissionPdf |cos_g(x_j, light)| / d_light^2; each strategy contributes f / (pA + pB).
class PathTracer {
public:
    PathTracer(const EmbreeState& state, const std::vector<scene::Light>& lights,
            const scene::CameraView& camera, int width, int height, int bounces)
        : mState(state), mLights(lights), mWidth(width), mHeight(height), mBounces(bounces) {
        const glm::dmat4 clipToWorld =
                glm::inverse(glm::dmat4(camera.projection) * glm::dmat4(camera.view));
        mNear[0] = clipToWorld * glm::dvec4(0.0, 0.0, -1.0, 1.0);
        mFar[0] = clipToWorld * glm::dvec4(0.0, 0.0, 1.0, 1.0);
        for (int axis = 0; axis < 2; ++axis) {
            glm::dvec4 unit(0.0);
            unit[axis] = 1.0;
            mNear[axis + 1] = mFar[axis + 1] = clipToWorld * unit;
        }
        for (const scene::Light& light : lights) mEmissionPdf.push_back(emissionPdf(light));
    }

    // One path through continuous image coordinates (x, y), x in [0, width) left to right,
    // y in [0, height) top to bottom. u[0..1]: the first bounce direction, u[2..3]: the first
    // light's emission direction; everything else comes from `rng`. `lightVertices` is scratch
    // space reused between calls.
    PathSample trace(float x, float y, const float u[4], Pcg32& rng,
            std::vector<LightVertex>& lightVertices, RayCounts& counts) const {
        PathSample result;
        RTCIntersectContext coherent, incoherent;
        rtcInitIntersectContext(&coherent);
        coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcInitIntersectContext(&incoherent);
        RTCRayHit rayHit = cameraRay(x, y);
        ++counts.primary;
        rtcIntersect1(mState.rtcScene, &coherent, &rayHit);
        Surface surface;
        if (!interact(rayHit, surface)) return result;
        result.hit = true;
        result.direct = surface.emission + directLight(surface, -1.0f, incoherent, counts);
        if (mBounces <= 0) return result;

        sampleLightVertices(u + 2, rng, lightVertices, incoherent, counts);
        glm::vec3 throughput(1.0f);
        for (int bounce = 0; bounce < mBounces; ++bounce) {
            if (maxComponent(throughput * surface.albedo) <= 0.0f) break;
            result.indirect += throughput * connect(surface, lightVertices, incoherent, counts);
            throughput *= surface.albedo;
            const float u1 = bounce == 0 ? u[0] : rng.nextFloat();
            const float u2 = bounce == 0 ? u[1] : rng.nextFloat();
            const glm::vec3 direction = sampleCosineHemisphere(surface.shadingNormal, u1, u2);
            const float cosSampled = glm::dot(direction, surface.shadingNormal);
            if (glm::dot(direction, surface.geometricNormal) <= 0.0f || cosSampled <= 0.0f) break;
            const glm::vec3 origin = offsetOrigin(surface);
            rayHit = ray(origin, direction, std::numeric_limits<float>::infinity());
            ++counts.bounce;
            rtcIntersect1(mState.rtcScene, &incoherent, &rayHit);
            if (!interact(rayHit, surface)) break;
            const glm::vec3 step = surface.position - origin;
            const float distance2 = glm::dot(step, step);
            const float pdfArea = cosSampled * glm::one_over_pi<float>() *
                    std::abs(glm::dot(surface.geometricNormal, direction)) /
                    std::max(distance2, std::numeric_limits<float>::min());
            result.indirect += throughput *
                    (surface.emission + directLight(surface, pdfArea, incoherent, counts));
        }
        return result;
    }

private:
    static RTCRayHit ray(const glm::vec3& origin, const glm::vec3& direction, float tfar) {
        RTCRayHit rayHit{};
        rayHit.ray.org_x = origin.x;
        rayHit.ray.org_y = origin.y;
        rayHit.ray.org_z = origin.z;
        rayHit.ray.dir_x = direction.x;
        rayHit.ray.dir_y = direction.y;
        rayHit.ray.dir_z = direction.z;
        rayHit.ray.tnear = 0.0f;
        rayHit.ray.tfar = tfar;
        rayHit.ray.mask = 0xFFFFFFFFu;
        rayHit.ray.time = 0.0f;
        rayHit.ray.flags = 0;
        rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
        rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        return rayHit;
    }

    // The ray through a point of the image, from the near plane to the far plane, exactly as
    // the raster passes clip it.
    RTCRayHit cameraRay(float x, float y) const {
        const double ndcX = 2.0 * double(x) / double(mWidth) - 1.0;
        const double ndcY = 1.0 - 2.0 * double(y) / double(mHeight);
        const glm::dvec4 nearH = mNear[0] + ndcX * mNear[1] + ndcY * mNear[2];
        const glm::dvec4 farH = mFar[0] + ndcX * mFar[1] + ndcY * mFar[2];
        const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
        const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
        const glm::dvec3 span = farP - nearP;
        const double length = glm::length(span);
        return ray(glm::vec3(nearP), glm::vec3(span / length), float(length));
    }

    static glm::vec3 offsetOrigin(const Surface& surface) {
        return surface.position + surface.offset * surface.geometricNormal;
    }

    bool interact(const RTCRayHit& rayHit, Surface& surface) const {
        if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        const std::uint32_t triangle = mState.firstTriangle[rayHit.hit.geomID] + rayHit.hit.primID;
        const glm::uvec3 t = mState.triangles[triangle];
        const float u = rayHit.hit.u, v = rayHit.hit.v, w = 1.0f - u - v;
        const glm::vec3& p0 = mState.positions[t.x];
        const glm::vec3& p1 = mState.positions[t.y];
        const glm::vec3& p2 = mState.positions[t.z];
        const glm::vec3 incoming(-rayHit.ray.dir_x, -rayHit.ray.dir_y, -rayHit.ray.dir_z);
        const TriangleInfo& info = mState.triangleInfo[triangle];

        surface.position = w * p0 + u * p1 + v * p2;
        glm::vec3 ng = info.normal == glm::vec3(0.0f) ? incoming : info.normal;
        if (glm::dot(ng, incoming) < 0.0f) ng = -ng;
        glm::vec3 ns = ng;
        if (info.flags & kSmoothNormals) {
            ns = w * mState.normals[t.x] + u * mState.normals[t.y] + v * mState.normals[t.z];
            const float nsLength = glm::length(ns);
            ns = nsLength > 0.0f && std::isfinite(nsLength) ? ns / nsLength : ng;
            if (glm::dot(ns, incoming) < 0.0f) ns = -ns;
        }
        surface.geometricNormal = ng;
        surface.shadingNormal = ns;
        surface.offset = info.offset;

        const ShadingMaterial& m = mState.materials[info.material];
        surface.albedo = glm::vec3(mState.baseColor(triangle, u, v));
        surface.emission = m.emissiveFactor;
        if (m.emissiveTexture && maxComponent(m.emissiveFactor) > 0.0f) {
            surface.emission *= glm::vec3(sampleTexture(*m.emissiveTexture,
                    mState.texcoord(triangle, m.emissiveTexCoord, u, v)));
        }
        return true;
    }

    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tfar,
            RTCIntersectContext& context, RayCounts& counts) const {
        RTCRay shadow = ray(origin, direction, tfar).ray;
        ++counts.shadow;
        rtcOccluded1(mState.rtcScene, &context, &shadow);
        return shadow.tfar < 0.0f;
    }

    // Outgoing radiance rho/pi x sum over lights of (colour x intensity x E) x visibility, with
    // E per DESIGN.md "Radiometric conventions". With pdfArea >= 0 (the density of this vertex
    // under cosine sampling from the previous one), contributions of lights that also have
    // light vertices carry the MIS weight pA / (pA + pB); with pdfArea < 0 (camera hit) none.
    glm::vec3 directLight(const Surface& surface, float pdfArea, RTCIntersectContext& context,
            RayCounts& counts) const {
        if (maxComponent(surface.albedo) <= 0.0f) return glm::vec3(0.0f);
        glm::vec3 sum(0.0f);
        const glm::vec3 origin = offsetOrigin(surface);
        for (std::size_t i = 0; i < mLights.size(); ++i) {
            const scene::Light& light = mLights[i];
            const glm::vec3 radiant = light.color * light.intensity;
            if (!usableLight(light, radiant)) continue;
            glm::vec3 wi;
            float distance = 0.0f, factor = 0.0f;
            if (!lightGeometry(light, surface.position, wi, distance, factor)) continue;
            const float cosTheta = glm::dot(surface.shadingNormal, wi);
            const float cosGeometric = glm::dot(surface.geometricNormal, wi);
            if (cosTheta <= 0.0f || cosGeometric <= 0.0f) continue;
            float tfar = distance;
            if (std::isfinite(distance)) {
                tfar = glm::length(light.position - origin) * (1.0f - kShadowRayShortening);
            }
            if (occluded(origin, wi, tfar, context, counts)) continue;
            float weight = 1.0f;
            if (pdfArea >= 0.0f && mEmissionPdf[i] > 0.0f) {
                const float pdfLight = mEmissionPdf[i] * cosGeometric / (distance * distance);
                weight = pdfArea / (pdfArea + pdfLight);
            }
            sum += radiant * (factor * cosTheta * weight);
        }
        return surface.albedo * glm::one_over_pi<float>() * sum;
    }

    // Samples one light vertex per point or spot light (the first light uses the stratified
    // numbers u[0..1], the others `rng`).
    void sampleLightVertices(const float u[2], Pcg32& rng, std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const {
        vertices.resize(mLights.size());
        for (std::size_t i = 0; i < mLights.size(); ++i) {
            LightVertex& vertex = vertices[i];
            vertex.valid = false;
            const scene::Light& light = mLights[i];
            if (mEmissionPdf[i] <= 0.0f) continue;
            const float u1 = i == 0 ? u[0] : rng.nextFloat();
            const float u2 = i == 0 ? u[1] : rng.nextFloat();
            const glm::vec3 radiant = light.color * light.intensity;
            if (!usableLight(light, radiant)) continue;
            const glm::vec3 direction = lightSubpathDirection(light, u1, u2);
            RTCRayHit rayHit =
                    ray(light.position, direction, std::numeric_limits<float>::infinity());
            ++counts.light;
            rtcIntersect1(mState.rtcScene, &context, &rayHit);
            if (!interact(rayHit, vertex.surface)) continue;
            const Surface& s = vertex.surface;
            glm::vec3 wi;
            float distance = 0.0f, factor = 0.0f;
            if (maxComponent(s.albedo) <= 0.0f ||
                    !lightGeometry(light, s.position, wi, distance, factor)) {
                continue;
            }
            const float cosTheta = glm::dot(s.shadingNormal, wi);
            if (cosTheta <= 0.0f) continue;
            vertex.radiance = s.albedo * glm::one_over_pi<float>() * radiant * (factor * cosTheta);
            vertex.pdfArea = mEmissionPdf[i] * std::abs(glm::dot(s.geometricNormal, wi)) /
                             (distance * distance);
            vertex.valid = vertex.pdfArea > 0.0f && std::isfinite(vertex.pdfArea);
        }
    }

    // Strategy (B): light reflected once at each light vertex y towards x, i.e.
    // rho_x/pi cos_s(x) |cos_g(y)| / d^2 x L_y x V(x, y) / (pA + pB).
    glm::vec3 connect(const Surface& x, const std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const {
        glm::vec3 sum(0.0f);
        for (const LightVertex& vertex : vertices) {
            if (!vertex.valid) continue;
            const Surface& y = vertex.surface;
            const glm::vec3 toY = y.position - x.position;
            const float distance2 = glm::dot(toY, toY);
            if (!(distance2 > 0.0f)) continue;
            const glm::vec3 w = toY / std::sqrt(distance2);
            const float cosX = glm::dot(x.shadingNormal, w);
            const float cosY = -glm::dot(y.geometricNormal, w);
            if (cosX <= 0.0f || glm::dot(x.geometricNormal, w) <= 0.0f || cosY <= 0.0f) continue;
            const float geometry = cosX * cosY / distance2;
            const float pdfBsdf = geometry * glm::one_over_pi<float>();
            if (!visible(x, y, context, counts)) continue;
            sum += vertex.radiance * (geometry / (pdfBsdf + vertex.pdfArea));
        }
        return x.albedo * glm::one_over_pi<float>() * sum;
    }

    // Whether the segment from x to y is free. A ray arriving at y at a grazing angle may touch
    // y's own plane a little before y by rounding; hits within that plane count as arriving.
    bool visible(const Surface& x, const Surface& y, RTCIntersectContext& context,
            RayCounts& counts) const {
        const glm::vec3 origin = offsetOrigin(x);
        const glm::vec3 span = y.position - origin;
        const float length = glm::length(span);
        if (!(length > 0.0f)) return false;
        const glm::vec3 direction = span / length;
        RTCRayHit rayHit = ray(origin, direction, length * (1.0f - kShadowRayShortening));
        ++counts.shadow;
        rtcIntersect1(mState.rtcScene, &context, &rayHit);
        if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return true;
        const glm::vec3 hit = origin + rayHit.ray.tfar * direction;
        return std::abs(glm::dot(hit - y.position, y.geometricNormal)) <= 4.0f * y.offset;
    }

    const EmbreeState& mState;
    const std::vector<scene::Light>& mLights;
    std::vector<float> mEmissionPdf;   // per light, emissionPdf()
    int mWidth, mHeight, mBounces;
    // Clip-to-world images of (ndcX, ndcY, -1 | +1, 1) = [0] + ndcX [1] + ndcY [2], homogeneous.
    glm::dvec4 mNear[3];
    glm::dvec4 mFar[3];
};

// Per-pixel half means, kept until the noise estimate is computed.
struct HalfImages {
    std::vector<glm::vec3> direct[2];
    std::vector<glm::vec3> indirect[2];
};

// One pixel's estimate: the mean radiance of each half of its paths.
struct PixelEstimate {
    glm::dvec3 direct[2];
    glm::dvec3 indirect[2];
    int hits = 0;   // paths whose camera ray hit geometry
};

// Traces pathsPerHalf[h] paths for each half h of pixel (x, y). Half h draws from its own
// streams seeded by (seed, pixel, h): Owen-scrambled Sobol' points for the pixel position,
// first bounce and first light, PCG32 for everything else.
PixelEstimate renderPixel(const PathTracer& tracer, int x, int y, std::uint64_t seed,
        std::size_t pixel, const int pathsPerHalf[2], std::vector<LightVertex>& lightVertices,
        RayCounts& rays) {
    PixelEstimate estimate;
    const std::uint64_t stream = mix64(seed ^ std::uint64_t(pixel));
    for (int h = 0; h < 2; ++h) {
        Pcg32 rng(stream, std::uint64_t(h));
        const OwenSobolSampler sampler(std::uint32_t(mix64(stream + std::uint64_t(h))));
        glm::dvec3 direct(0.0), indirect(0.0);
        for (int s = 0; s < pathsPerHalf[h]; ++s) {
            float u[kSobolDimensions];
            sampler.point(std::uint32_t(s), u);
            const PathSample path =
                    tracer.trace(float(x) + u[0], float(y) + u[1], u + 2, rng, lightVertices, rays);
            direct += glm::dvec3(path.direct);
            indirect += glm::dvec3(path.indirect);
            estimate.hits += path.hit ? 1 : 0;
        }
        const double n = double(std::max(pathsPerHalf[h], 1));
        estimate.direct[h] = direct / n;
        estimate.indirect[h] = indirect / n;
    }
    return estimate;
}

double relativeNoise(const HalfImages& halves, const core::Image& combined,
        const std::vector<float>& coverage, bool directPart, bool indirectPart, int spp) {
    if (spp < 2) return std::numeric_limits<double>::quiet_NaN();
    const double nA = double((spp + 1) / 2), nB = double(spp / 2);
    const double factor = nA * nB / (double(spp) * double(spp));
    double difference = 0.0, energy = 0.0;
    std::size_t pixels = 0;
    for (std::size_t p = 0; p < coverage.size(); ++p) {
        if (!(coverage[p] > kGeometryCoverage)) continue;
        ++pixels;
        glm::dvec3 a(0.0), b(0.0);
        if (directPart) {
            a += glm::dvec3(halves.direct[0][p]);
            b += glm::dvec3(halves.direct[1][p]);
        }
        if (indirectPart) {
            a += glm::dvec3(halves.indirect[0][p]);
            b += glm::dvec3(halves.indirect[1][p]);
        }
        const glm::dvec3 d = a - b;
        difference += glm::dot(d, d);
        const glm::dvec3 c(combined.rgb[3 * p], combined.rgb[3 * p + 1], combined.rgb[3 * p + 2]);
        energy += glm::dot(c, c);
    }
    if (pixels == 0) return std::numeric_limits<double>::quiet_NaN();
    if (energy <= 0.0) return difference <= 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return std::sqrt(difference * factor / energy);
}

} // namespace

ReferenceRenderer::ReferenceRenderer(const scene::Scene& scene) : mScene(scene) {
    const auto start = std::chrono::steady_clock::now();
    auto state = std::make_unique<EmbreeState>();
    fillState(scene, *state);
    state->device = rtcNewDevice(nullptr);
    if (!state->device) {
        mError = "cannot create the Embree device (error " +
                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")";
        return;
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
        mError = "Embree scene build failed: " +
                 (state->deviceError.empty() ? std::string("out of memory") : state->deviceError);
        return;
    }
    state->buildSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    mState = std::move(state);
}

ReferenceRenderer::~ReferenceRenderer() = default;

bool ReferenceRenderer::valid() const { return mState != nullptr; }

double ReferenceRenderer::buildSeconds() const { return mState ? mState->buildSeconds : 0.0; }

ReferenceResult ReferenceRenderer::render(const scene::CameraView& camera, int width, int height,
        const ReferenceSettings& settings, const ProgressCallback& progress) const {
    ReferenceResult result;
    if (!mState || width <= 0 || height <= 0) return result;
    const auto start = std::chrono::steady_clock::now();
    const int spp = std::max(settings.spp, 1);
    const int bounces = std::max(settings.bounces, 0);
    const std::size_t pixelCount = std::size_t(width) * std::size_t(height);
    result.direct = core::Image(width, height);
    result.indirect = core::Image(width, height);
    result.final = core::Image(width, height);
    result.coverage.assign(pixelCount, 0.0f);
    result.spp = spp;
    result.bounces = bounces;

    HalfImages halves;
    for (int h = 0; h < 2; ++h) {
        halves.direct[h].assign(pixelCount, glm::vec3(0.0f));
        halves.indirect[h].assign(pixelCount, glm::vec3(0.0f));
    }

    const PathTracer tracer(*mState, mScene.lights, camera, width, height, bounces);
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    const std::uint64_t seed = mix64(std::uint64_t(std::uint32_t(settings.seed)));
    const int pathsPerHalf[2] = {(spp + 1) / 2, spp / 2};

    std::atomic<int> nextTile{0};
    std::mutex progressMutex;
    std::size_t pixelsDone = 0;
    double lastReported = -1.0;
    RayCounts totalRays;

    auto worker = [&] {
        RayCounts rays;
        std::vector<LightVertex> lightVertices;
        for (int tile = nextTile++; tile < tileCount; tile = nextTile++) {
            const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
                    const PixelEstimate e = renderPixel(tracer, x, y, seed, pixel, pathsPerHalf,
                            lightVertices, rays);
                    const double wA = double(pathsPerHalf[0]) / spp;
                    const double wB = double(pathsPerHalf[1]) / spp;
                    const glm::dvec3 direct = wA * e.direct[0] + wB * e.direct[1];
                    const glm::dvec3 indirect = wA * e.indirect[0] + wB * e.indirect[1];
                    result.direct.set(x, y, glm::vec3(direct));
                    result.indirect.set(x, y, glm::vec3(indirect));
                    result.final.set(x, y, glm::vec3(direct + indirect));
                    result.coverage[pixel] = float(double(e.hits) / double(spp));
                    for (int h = 0; h < 2; ++h) {
                        halves.direct[h][pixel] = glm::vec3(e.direct[h]);
                        halves.indirect[h][pixel] = glm::vec3(e.indirect[h]);
                    }
                }
            }
            const std::lock_guard<std::mutex> lock(progressMutex);
            pixelsDone += std::size_t(x1 - x0) * std::size_t(y1 - y0);
            const double fraction = double(pixelsDone) / double(pixelCount);
            if (progress && fraction < 1.0 && fraction > lastReported) {
                lastReported = fraction;
                progress(fraction);
            }
        }
        const std::lock_guard<std::mutex> lock(progressMutex);
        totalRays.primary += rays.primary;
        totalRays.shadow += rays.shadow;
        totalRays.bounce += rays.bounce;
        totalRays.light += rays.light;
    };

    int threads = settings.threads > 0 ? settings.threads
                                       : int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::clamp(threads, 1, tileCount);
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
    if (progress) progress(1.0);

    result.rays = totalRays;
    result.noise.direct = relativeNoise(halves, result.direct, result.coverage, true, false, spp);
    result.noise.indirect =
            relativeNoise(halves, result.indirect, result.coverage, false, true, spp);
    result.noise.final = relativeNoise(halves, result.final, result.coverage, true, true, spp);
    result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

ReferenceResult renderReference(const scene::Scene& scene, const scene::CameraView& camera,
        int width, int height, const ReferenceSettings& settings,
        const ProgressCallback& progress) {
    const ReferenceRenderer renderer(scene);
    return renderer.render(camera, width, height, settings, progress);
}

} // namespace gi::reference
