// SceneBuilder's animations: the node hierarchy copied into the Scene and every animation
// channel validated (glTF 2.0 section 3.11); the instances they move become dynamic and the
// scene bounds grow to cover every pose.
#include "scene/GltfSceneBuilder.h"

#include "scene/Animation.h"
#include "scene/GltfMessages.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace gi::scene::gltf {

// The node hierarchy and every animation channel (glTF 2.0 section 3.11), validated;
// then the instances they move are marked dynamic and the bounds cover every pose.
bool SceneBuilder::readAnimations() {
    mScene.nodes.resize(mModel.nodes.size());
    for (std::size_t i = 0; i < mModel.nodes.size(); ++i) {
        const tinygltf::Node& node = mModel.nodes[i];
        SceneNode& out = mScene.nodes[i];
        out.parent = mParent[i];
        out.matrix = mLocal[i];
        out.hasMatrix = !node.matrix.empty();
        // localTransform validated these arrays.
        if (node.translation.size() == 3) {
            out.translation = glm::make_vec3(node.translation.data());
        }
        if (node.scale.size() == 3) out.scale = glm::make_vec3(node.scale.data());
        if (node.rotation.size() == 4) {
            out.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0],
                    node.rotation[1], node.rotation[2]));
        }
    }
    bool warnedWeights = false;
    for (std::size_t a = 0; a < mModel.animations.size(); ++a) {
        const tinygltf::Animation& source = mModel.animations[a];
        Animation animation;
        animation.name = source.name.empty() ? indexed("animations", long(a)) : source.name;
        for (std::size_t c = 0; c < source.channels.size(); ++c) {
            const std::string element =
                    indexed("animations", long(a)) + ".channels[" + std::to_string(c) + "]";
            AnimationChannel channel;
            if (!readChannel(source, source.channels[c], element, channel, warnedWeights)) {
                return false;
            }
            if (channel.node < 0) continue;   // a skipped (morph weights) channel
            animation.duration = std::max(animation.duration, channel.times.back());
            animation.channels.push_back(std::move(channel));
        }
        if (!animation.channels.empty()) mScene.animations.push_back(std::move(animation));
    }
    markDynamicInstances(mScene);
    mScene.bounds = animatedBounds(mScene);
    return true;
}

// A channel's target and interpolation; morph target weights are skipped (out.node stays < 0).
bool SceneBuilder::readChannel(const tinygltf::Animation& animation,
        const tinygltf::AnimationChannel& in, const std::string& element, AnimationChannel& out,
        bool& warnedWeights) {
    if (in.target_path == "weights") {
        if (!warnedWeights) warn(element, "morph target weights are not animated; skipped");
        warnedWeights = true;
        return true;
    }
    if (in.target_path == "translation") out.path = AnimationPath::Translation;
    else if (in.target_path == "rotation") out.path = AnimationPath::Rotation;
    else if (in.target_path == "scale") out.path = AnimationPath::Scale;
    else return fail(element, "target.path '" + in.target_path + "' is not translation, "
                              "rotation, scale or weights");
    if (in.target_node < 0 || std::size_t(in.target_node) >= mModel.nodes.size()) {
        return fail(element, doesNotExist("target.node", in.target_node, mModel.nodes.size(),
                                     "nodes"));
    }
    if (!mModel.nodes[std::size_t(in.target_node)].matrix.empty()) {
        return fail(element, indexed("nodes", in.target_node) +
                                     " has a matrix, and glTF forbids animating such nodes");
    }
    if (in.sampler < 0 || std::size_t(in.sampler) >= animation.samplers.size()) {
        return fail(element, doesNotExist("sampler", in.sampler, animation.samplers.size(),
                                     "samplers of its animation"));
    }
    const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(in.sampler)];
    if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR") {
        out.interpolation = AnimationInterpolation::Linear;
    } else if (sampler.interpolation == "STEP") {
        out.interpolation = AnimationInterpolation::Step;
    } else if (sampler.interpolation == "CUBICSPLINE") {
        out.interpolation = AnimationInterpolation::CubicSpline;
    } else {
        return fail(element, "interpolation '" + sampler.interpolation +
                                     "' is not LINEAR, STEP or CUBICSPLINE");
    }
    return readChannelKeys(sampler, in, element, out);
}

// Key times (non-negative, strictly increasing) and the values matching the target's path.
bool SceneBuilder::readChannelKeys(const tinygltf::AnimationSampler& sampler,
        const tinygltf::AnimationChannel& in, const std::string& element,
        AnimationChannel& out) {
    AccessorFloats input, output;
    std::string error;
    for (const auto& [index, data] :
            {std::pair{sampler.input, &input}, {sampler.output, &output}}) {
        if (index < 0 || std::size_t(index) >= mModel.accessors.size()) {
            return fail(element, doesNotExist("sampler accessor", index,
                                         mModel.accessors.size(), "accessors"));
        }
        if (!readAccessorFloats(mModel, index, mLimits.maxAccessorCount, *data, error)) {
            return failWith(error);
        }
        for (float v : data->values) {
            if (!std::isfinite(v)) {
                return fail(element, indexed("accessors", index) + " holds a non-finite value");
            }
        }
    }
    const int components = out.path == AnimationPath::Rotation ? 4 : 3;
    const std::size_t perKey = out.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1;
    if (input.components != 1 || input.count == 0) {
        return fail(element, "its sampler's input must be a non-empty SCALAR accessor of times");
    }
    for (std::size_t k = 0; k < input.count; ++k) {
        if (input.values[k] < 0.0f || (k > 0 && !(input.values[k] > input.values[k - 1]))) {
            return fail(element, "key times must be >= 0 and strictly increasing (key " +
                                         std::to_string(k) + ")");
        }
    }
    if (output.components != components || output.count != input.count * perKey) {
        return fail(element, "its sampler's output has " + std::to_string(output.count) +
                                     " elements of " + std::to_string(output.components) +
                                     " components; " + in.target_path + " needs " +
                                     std::to_string(input.count * perKey) + " of " +
                                     std::to_string(components));
    }
    out.node = in.target_node;
    out.times = input.values;
    out.values.resize(output.count, glm::vec4(0.0f));
    for (std::size_t k = 0; k < output.count; ++k) {
        for (int i = 0; i < components; ++i) {
            out.values[k][i] = output.values[k * std::size_t(components) + std::size_t(i)];
        }
    }
    return true;
}

} // namespace gi::scene::gltf
