#include "scene/EmissionLights.h"

#include "core/Colour.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace gi::scene {
namespace {

constexpr float kMaxLightSpan = 0.25f;  // of the scene's diagonal

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

int wrap(int i, int n, int mode) {
    if (mode == 33071) return std::clamp(i, 0, n - 1);   // CLAMP_TO_EDGE
    if (mode == 33648) {                                   // MIRRORED_REPEAT
        const int period = 2 * n;
        int m = ((i % period) + period) % period;
        return m < n ? m : period - 1 - m;
    }
    return ((i % n) + n) % n;                              // REPEAT
}

// The texture's linear RGB at uv, nearest texel (the mean over a triangle needs no filter).
glm::vec3 texel(const Texture& texture, glm::vec2 uv) {
    if (texture.width <= 0 || texture.height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        return glm::vec3(1.0f);
    }
    const int x = wrap(int(std::floor(uv.x * float(texture.width))), texture.width, texture.wrapS);
    const int y = wrap(int(std::floor(uv.y * float(texture.height))), texture.height, texture.wrapT);
    const std::uint8_t* p = &texture.rgba8[(std::size_t(y) * std::size_t(texture.width) + std::size_t(x)) * 4];
    glm::vec3 c;
    for (int k = 0; k < 3; ++k) {
        c[k] = texture.srgb ? core::srgbToLinear(float(p[k]) / 255.0f) : float(p[k]) / 255.0f;
    }
    return c;
}

// The emissive texture's mean over a triangle, from its centre and three points halfway
// between the centre and each corner.
glm::vec3 meanEmissiveTexture(const Texture& texture, const glm::vec2 uv[3]) {
    const glm::vec2 centre = (uv[0] + uv[1] + uv[2]) / 3.0f;
    glm::vec3 sum = texel(texture, centre);
    for (int k = 0; k < 3; ++k) sum += texel(texture, 0.5f * (centre + uv[k]));
    return 0.25f * sum;
}

struct Cluster {
    std::vector<std::size_t> members;   // into the emitter list
    Aabb centres;
    float span = 0.0f;                  // diagonal of the members' bounds (m)
};

Cluster makeCluster(const std::vector<EmitterTriangle>& emitters, std::vector<std::size_t> members) {
    Cluster c;
    c.members = std::move(members);
    Aabb bounds;
    for (std::size_t i : c.members) {
        const EmitterTriangle& t = emitters[i];
        c.centres.extend((t.p0 + t.p1 + t.p2) / 3.0f);
        bounds.extend(t.p0);
        bounds.extend(t.p1);
        bounds.extend(t.p2);
    }
    c.span = glm::length(bounds.size());
    return c;
}

Light lightFromCluster(const std::vector<EmitterTriangle>& emitters, const Cluster& cluster,
        std::size_t number) {
    Light light;
    light.type = LightType::Area;
    light.name = "emissive surface " + std::to_string(number);
    glm::vec3 weighted(0.0f);
    float area = 0.0f;
    for (std::size_t i : cluster.members) {
        const EmitterTriangle& t = emitters[i];
        light.emitters.push_back(t);
        weighted += t.area() * (t.p0 + t.p1 + t.p2) / 3.0f;
        area += t.area();
    }
    light.position = area > 0.0f ? weighted / area : cluster.centres.center();
    glm::vec3 normal(0.0f);
    for (const EmitterTriangle& t : light.emitters) normal += t.area() * t.normal();
    light.direction = glm::length(normal) > 0.0f ? glm::normalize(normal) : glm::vec3(0.0f, -1.0f, 0.0f);
    light.color = glm::vec3(1.0f);
    light.intensity = 1.0f;
    return light;
}

// Splits the cluster that most needs it (most triangles, then widest) until none needs it.
std::vector<Cluster> clusterEmitters(const std::vector<EmitterTriangle>& emitters, float maxSpan) {
    std::vector<std::size_t> all(emitters.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    std::vector<Cluster> clusters{makeCluster(emitters, all)};
    auto needsSplit = [&](const Cluster& c) {
        return c.members.size() > 1 && (c.members.size() > kMaxTrianglesPerLight || c.span > maxSpan);
    };
    while (clusters.size() < kMaxAreaLights) {
        auto worst = std::max_element(clusters.begin(), clusters.end(),
                [&](const Cluster& a, const Cluster& b) {
                    const bool sa = needsSplit(a), sb = needsSplit(b);
                    if (sa != sb) return !sa;
                    return a.members.size() != b.members.size() ? a.members.size() < b.members.size()
                                                                : a.span < b.span;
                });
        if (!needsSplit(*worst)) break;
        const glm::vec3 size = worst->centres.size();
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
        std::vector<std::size_t> members = worst->members;
        auto centre = [&](std::size_t i) {
            const EmitterTriangle& t = emitters[i];
            return (t.p0[axis] + t.p1[axis] + t.p2[axis]) / 3.0f;
        };
        const auto middle = members.begin() + std::ptrdiff_t(members.size() / 2);
        std::nth_element(members.begin(), middle, members.end(),
                [&](std::size_t a, std::size_t b) { return centre(a) < centre(b); });
        std::vector<std::size_t> low(members.begin(), middle), high(middle, members.end());
        *worst = makeCluster(emitters, std::move(low));
        clusters.push_back(makeCluster(emitters, std::move(high)));
    }
    return clusters;
}

} // namespace

double emitterPower(const EmitterTriangle& triangle) {
    return glm::pi<double>() * double(luminance(triangle.radiance)) * double(triangle.area()) *
           (triangle.twoSided ? 2.0 : 1.0);
}

EmissionLightsReport addEmissionLights(Scene& scene) {
    EmissionLightsReport report;
    std::vector<EmitterTriangle> emitters;
    double sceneArea = 0.0, emittingArea = 0.0;
    for (std::size_t instanceIndex = 0; instanceIndex < scene.instances.size(); ++instanceIndex) {
        const Instance& instance = scene.instances[instanceIndex];
        const Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        const Material* material = primitive.material >= 0
                ? &scene.materials[std::size_t(primitive.material)] : nullptr;
        const bool emits = material && luminance(material->emissiveFactor) > 0.0f;
        const Texture* texture = emits && material->emissiveTexture >= 0
                ? &scene.textures[std::size_t(material->emissiveTexture)] : nullptr;
        const std::vector<glm::vec2>& uvs = material && material->emissiveTexCoord == 1
                ? primitive.texcoords1 : primitive.texcoords0;
        for (std::size_t k = 0; k + 2 < primitive.indices.size(); k += 3) {
            EmitterTriangle t;
            const std::uint32_t* index = &primitive.indices[k];
            t.p0 = glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[index[0]], 1.0f));
            t.p1 = glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[index[1]], 1.0f));
            t.p2 = glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[index[2]], 1.0f));
            const double area = double(t.area());
            if (!std::isfinite(area)) continue;
            sceneArea += area;
            if (!emits || !(area > 0.0)) continue;
            t.radiance = material->emissiveFactor;
            if (texture && uvs.size() == primitive.positions.size()) {
                const glm::vec2 uv[3] = {uvs[index[0]], uvs[index[1]], uvs[index[2]]};
                t.radiance *= meanEmissiveTexture(*texture, uv);
            }
            if (!(luminance(t.radiance) > 0.0f)) continue;
            t.twoSided = material->doubleSided;
            t.instance = int(instanceIndex);
            t.triangle = int(k / 3);
            t.material = primitive.material;
            emittingArea += area;
            emitters.push_back(t);
        }
    }
    report.emittingTriangles = emitters.size();
    if (emitters.empty()) return report;
    report.emittingAreaShare = sceneArea > 0.0 ? emittingArea / sceneArea : 0.0;

    double totalPower = 0.0;
    for (const EmitterTriangle& t : emitters) totalPower += emitterPower(t);
    if (emitters.size() > kMaxEmitterTriangles) {
        std::nth_element(emitters.begin(), emitters.begin() + std::ptrdiff_t(kMaxEmitterTriangles),
                emitters.end(), [](const EmitterTriangle& a, const EmitterTriangle& b) {
                    return emitterPower(a) > emitterPower(b);
                });
        emitters.resize(kMaxEmitterTriangles);
        double kept = 0.0;
        for (const EmitterTriangle& t : emitters) kept += emitterPower(t);
        report.droppedPowerShare = totalPower > 0.0 ? 1.0 - kept / totalPower : 0.0;
    }
    report.lightTriangles = emitters.size();

    const float maxSpan = kMaxLightSpan * std::max(glm::length(scene.bounds.size()), 1e-6f);
    const std::vector<Cluster> clusters = clusterEmitters(emitters, maxSpan);
    for (const Cluster& cluster : clusters) {
        scene.lights.push_back(lightFromCluster(emitters, cluster, report.lights));
        ++report.lights;
    }
    char line[256];
    std::snprintf(line, sizeof line, "%zu emissive triangle(s) (%.2g%% of the surface area) as %zu area light(s)",
            report.lightTriangles, 100.0 * report.emittingAreaShare, report.lights);
    report.summary = line;
    if (report.droppedPowerShare > 0.0) {
        std::snprintf(line, sizeof line, "; the %zu weakest of %zu left out (%.2g%% of the emitted flux)",
                report.emittingTriangles - report.lightTriangles, report.emittingTriangles,
                100.0 * report.droppedPowerShare);
        report.summary += line;
    }
    return report;
}

} // namespace gi::scene
