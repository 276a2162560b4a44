#include "scene/Animation.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gi::scene {
namespace {

glm::dquat toQuat(const glm::vec4& v) { return glm::dquat(v.w, v.x, v.y, v.z); }

glm::vec4 slerpValues(const glm::vec4& a, const glm::vec4& b, float t) {
    const glm::dquat q = glm::slerp(toQuat(a), toQuat(b), double(t));
    return glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w));
}

// Each node's local transform at `seconds`; nodes without channels keep their rest pose.
std::vector<glm::dmat4> localTransforms(const Scene& scene, double seconds) {
    std::vector<glm::dmat4> local(scene.nodes.size());
    std::vector<glm::dvec3> translation(scene.nodes.size()), scale(scene.nodes.size());
    std::vector<glm::dquat> rotation(scene.nodes.size());
    std::vector<bool> animated(scene.nodes.size(), false);
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        translation[i] = scene.nodes[i].translation;
        rotation[i] = scene.nodes[i].rotation;
        scale[i] = scene.nodes[i].scale;
    }
    for (const Animation& animation : scene.animations) {
        for (const AnimationChannel& channel : animation.channels) {
            const auto n = std::size_t(channel.node);
            const glm::vec4 v = sampleChannel(channel, float(seconds));
            animated[n] = true;
            switch (channel.path) {
            case AnimationPath::Translation: translation[n] = glm::dvec3(v); break;
            case AnimationPath::Scale: scale[n] = glm::dvec3(v); break;
            case AnimationPath::Rotation: {
                const glm::dquat q = toQuat(v);
                const double length = glm::length(q);
                rotation[n] = length > 1e-12 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
                break;
            }
            }
        }
    }
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        local[i] = animated[i] ? glm::translate(glm::dmat4(1.0), translation[i]) *
                                         glm::mat4_cast(rotation[i]) *
                                         glm::scale(glm::dmat4(1.0), scale[i])
                               : scene.nodes[i].matrix;
    }
    return local;
}

glm::dmat4 worldOf(const Scene& scene, const std::vector<glm::dmat4>& local, int node) {
    glm::dmat4 world(1.0);
    // The loader refused cycles, so walking up ends; parents multiply on the left.
    for (int n = node; n >= 0; n = scene.nodes[std::size_t(n)].parent) {
        world = local[std::size_t(n)] * world;
    }
    return world;
}

} // namespace

glm::vec4 sampleChannel(const AnimationChannel& channel, float seconds) {
    const std::vector<float>& times = channel.times;
    const bool cubic = channel.interpolation == AnimationInterpolation::CubicSpline;
    const auto value = [&](std::size_t key) { return channel.values[cubic ? 3 * key + 1 : key]; };
    if (times.empty()) return glm::vec4(0.0f);
    if (!(seconds > times.front())) return value(0);
    if (seconds >= times.back()) return value(times.size() - 1);
    const std::size_t next =
            std::size_t(std::upper_bound(times.begin(), times.end(), seconds) - times.begin());
    const std::size_t key = next - 1;
    const float span = times[next] - times[key];
    const float t = (seconds - times[key]) / span;
    switch (channel.interpolation) {
    case AnimationInterpolation::Step: return value(key);
    case AnimationInterpolation::Linear:
        return channel.path == AnimationPath::Rotation ? slerpValues(value(key), value(next), t)
                                                        : glm::mix(value(key), value(next), t);
    case AnimationInterpolation::CubicSpline: {
        // Hermite basis with tangents scaled by the key interval (glTF 2.0 Appendix C).
        const glm::vec4 p0 = value(key), m0 = span * channel.values[3 * key + 2];
        const glm::vec4 p1 = value(next), m1 = span * channel.values[3 * next];
        const float t2 = t * t, t3 = t2 * t;
        glm::vec4 v = (2.0f * t3 - 3.0f * t2 + 1.0f) * p0 + (t3 - 2.0f * t2 + t) * m0 +
                      (-2.0f * t3 + 3.0f * t2) * p1 + (t3 - t2) * m1;
        if (channel.path == AnimationPath::Rotation) {
            const float length = glm::length(v);
            v = length > 0.0f ? v / length : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        }
        return v;
    }
    }
    return value(key);
}

float animationDuration(const Scene& scene) {
    float duration = 0.0f;
    for (const Animation& animation : scene.animations) duration = std::max(duration, animation.duration);
    return duration;
}

void markDynamicInstances(Scene& scene) {
    std::vector<bool> targeted(scene.nodes.size(), false);
    for (const Animation& animation : scene.animations) {
        for (const AnimationChannel& channel : animation.channels) {
            targeted[std::size_t(channel.node)] = true;
        }
    }
    for (Instance& instance : scene.instances) {
        instance.dynamic = false;
        for (int n = instance.node; n >= 0 && !instance.dynamic; n = scene.nodes[std::size_t(n)].parent) {
            instance.dynamic = targeted[std::size_t(n)];
        }
    }
}

void poseScene(Scene& scene, double seconds) {
    const double duration = animationDuration(scene);
    if (duration <= 0.0 || scene.nodes.empty()) return;
    const double t = std::fmod(std::max(seconds, 0.0), duration);
    const std::vector<glm::dmat4> local = localTransforms(scene, t);
    for (Instance& instance : scene.instances) {
        if (!instance.dynamic) continue;
        glm::dmat4 world = worldOf(scene, local, instance.node);
        world[3] -= glm::dvec4(glm::dvec3(scene.origin), 0.0);
        instance.worldFromLocal = glm::mat4(world);
    }
}

Aabb animatedBounds(const Scene& scene, int samples) {
    Aabb bounds = scene.bounds;
    const double duration = animationDuration(scene);
    if (duration <= 0.0) return bounds;
    for (int i = 0; i <= samples; ++i) {
        const std::vector<glm::dmat4> local =
                localTransforms(scene, duration * double(i) / double(samples) * (1.0 - 1e-9));
        for (const Instance& instance : scene.instances) {
            if (!instance.dynamic) continue;
            glm::dmat4 world = worldOf(scene, local, instance.node);
            world[3] -= glm::dvec4(glm::dvec3(scene.origin), 0.0);
            const Aabb& box = scene.primitives[std::size_t(instance.primitive)].localBounds;
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? box.max.x : box.min.x,
                        (c & 2) ? box.max.y : box.min.y, (c & 4) ? box.max.z : box.min.z);
                bounds.extend(glm::vec3(world * glm::dvec4(corner, 1.0)));
            }
        }
    }
    return bounds;
}

} // namespace gi::scene
