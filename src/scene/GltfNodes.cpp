// SceneBuilder's node hierarchy: local transforms and references checked, one parent per node
// and no cycles, then the selected scene walked to place mesh primitives (as instances),
// cameras and KHR_lights_punctual lights in world space.
#include "scene/GltfSceneBuilder.h"

#include "scene/GltfMessages.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <set>

namespace gi::scene::gltf {

// Local transforms, references and the hierarchy of every node: one parent at most, no
// cycles (glTF 2.0 section 3.5.2).
bool SceneBuilder::checkNodes() {
    const std::size_t count = mModel.nodes.size();
    mParent.assign(count, -1);
    mLocal.assign(count, glm::dmat4(1.0));
    for (std::size_t i = 0; i < count; ++i) {
        const tinygltf::Node& node = mModel.nodes[i];
        const std::string element = indexed("nodes", long(i));
        if (node.mesh < -1 || node.mesh >= int(mModel.meshes.size())) {
            return fail(element, doesNotExist("mesh", node.mesh, mModel.meshes.size(),
                                         "meshes"));
        }
        if (node.camera < -1 || node.camera >= int(mModel.cameras.size())) {
            return fail(element, doesNotExist("camera", node.camera, mModel.cameras.size(),
                                         "cameras"));
        }
        if (!localTransform(node, element, mLocal[i])) return false;
        for (int child : node.children) {
            if (child < 0 || std::size_t(child) >= count) {
                return fail(element, doesNotExist("child", child, count, "nodes"));
            }
            int& parent = mParent[std::size_t(child)];
            if (parent == int(i)) {
                return fail(indexed("nodes", child),
                        "is listed twice in " + element + ".children");
            }
            if (parent != -1) {
                return fail(indexed("nodes", child), "has two parents (" +
                                                             indexed("nodes", parent) +
                                                             " and " + element + ")");
            }
            parent = int(i);
        }
    }
    // With one parent per node, a cycle is a loop of parent links: walk up from every node,
    // marking the walk, until reaching a root or a node already known to reach one.
    std::vector<int> walk(count, -1); // start node of the walk that visited it
    std::vector<char> reachesRoot(count, 0);
    for (std::size_t start = 0; start < count; ++start) {
        int n = int(start);
        while (n != -1 && !reachesRoot[std::size_t(n)]) {
            if (walk[std::size_t(n)] == int(start)) return failCycle(n);
            walk[std::size_t(n)] = int(start);
            n = mParent[std::size_t(n)];
        }
        for (n = int(start); n != -1 && !reachesRoot[std::size_t(n)];
                n = mParent[std::size_t(n)]) {
            reachesRoot[std::size_t(n)] = 1;
        }
    }
    return true;
}

bool SceneBuilder::failCycle(int member) {
    std::vector<int> loop{member};
    for (int n = mParent[std::size_t(member)]; n != member; n = mParent[std::size_t(n)]) {
        loop.push_back(n);
    }
    std::reverse(loop.begin(), loop.end()); // parent -> child order
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    std::string path;
    const std::size_t shown = std::min<std::size_t>(loop.size(), 8);
    for (std::size_t k = 0; k < shown; ++k) path += indexed("nodes", loop[k]) + " -> ";
    path += loop.size() > shown ? "... -> " + indexed("nodes", loop.front())
                                : indexed("nodes", loop.front());
    return fail(indexed("nodes", loop.front()), "is part of a cycle in the node hierarchy (" +
                                                        path + ")");
}

bool SceneBuilder::localTransform(
        const tinygltf::Node& node, const std::string& element, glm::dmat4& out) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16 || !allFinite(node.matrix)) {
            return fail(element, "matrix must be 16 finite numbers");
        }
        out = glm::make_mat4(node.matrix.data());
        return true;
    }
    glm::dvec3 translation(0.0), scale(1.0);
    glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3 || !allFinite(node.translation)) {
            return fail(element, "translation must be 3 finite numbers");
        }
        translation = glm::make_vec3(node.translation.data());
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3 || !allFinite(node.scale)) {
            return fail(element, "scale must be 3 finite numbers");
        }
        scale = glm::make_vec3(node.scale.data());
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4 || !allFinite(node.rotation)) {
            return fail(element, "rotation must be 4 finite numbers");
        }
        // glTF stores quaternions as (x, y, z, w).
        rotation = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1],
                node.rotation[2]);
        const double length = glm::length(rotation);
        if (!(length > 1e-12) || !finite(length)) {
            return fail(element, "rotation is not a unit quaternion");
        }
        rotation /= length;
    }
    out = glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) *
          glm::scale(glm::dmat4(1.0), scale);
    return true;
}

bool SceneBuilder::selectRoots(std::vector<int>& roots) {
    if (mModel.scenes.empty()) {
        for (std::size_t i = 0; i < mModel.nodes.size(); ++i) {
            if (mParent[i] == -1) roots.push_back(int(i));
        }
        return true;
    }
    int sceneIndex = mModel.defaultScene;
    if (sceneIndex < -1 || sceneIndex >= int(mModel.scenes.size())) {
        return fail("scene", doesNotExist("scene", sceneIndex, mModel.scenes.size(),
                                     "scenes"));
    }
    if (sceneIndex == -1) sceneIndex = 0;
    const std::string element = indexed("scenes", sceneIndex);
    std::set<int> seen;
    for (int root : mModel.scenes[std::size_t(sceneIndex)].nodes) {
        if (root < 0 || std::size_t(root) >= mModel.nodes.size()) {
            return fail(element, doesNotExist("node", root, mModel.nodes.size(), "nodes"));
        }
        if (mParent[std::size_t(root)] != -1) {
            return fail(element, indexed("nodes", root) + " is listed as a root but is a "
                                         "child of " +
                                         indexed("nodes", mParent[std::size_t(root)]));
        }
        if (!seen.insert(root).second) {
            return fail(element, indexed("nodes", root) + " is listed twice");
        }
        roots.push_back(root);
    }
    return true;
}

// Walks the selected scene's node trees (iteratively: hostile files nest deeply) and
// places primitives, cameras and lights.
bool SceneBuilder::instantiate() {
    std::vector<int> roots;
    if (!selectRoots(roots)) return false;
    struct Item {
        int node;
        glm::dmat4 parentWorld;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        stack.push_back({*it, glm::dmat4(1.0)});
    }
    bool warnedSkin = false;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = mModel.nodes[std::size_t(item.node)];
        const std::string element = indexed("nodes", item.node);
        const glm::dmat4 world = item.parentWorld * mLocal[std::size_t(item.node)];
        if (!finiteMatrix(world)) {
            return fail(element, "world transform is not finite");
        }
        if (node.skin >= 0 && !warnedSkin) {
            warn(element, "skinning is ignored; meshes are drawn in their bind pose");
            warnedSkin = true;
        }
        if (node.mesh >= 0 && !placeMesh(item.node, world)) return false;
        if (node.camera >= 0 && !placeCamera(item.node, world)) return false;
        if (!placeLight(item.node, world)) return false;
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
            stack.push_back({*it, world});
        }
    }
    return true;
}

bool SceneBuilder::placeMesh(int nodeIndex, const glm::dmat4& world) {
    const int mesh = mModel.nodes[std::size_t(nodeIndex)].mesh;
    const bool flipped = glm::determinant(glm::dmat3(world)) < 0.0;
    const auto& primitives = mModel.meshes[std::size_t(mesh)].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        int sceneIndex = -1;
        if (!primitiveFor(mesh, int(p), flipped, sceneIndex)) return false;
        if (sceneIndex < 0) continue;
        if (mScene.instances.size() >= mLimits.maxInstances) {
            return fail(indexed("nodes", nodeIndex),
                    "the scene places more than the loader's limit of " +
                            std::to_string(mLimits.maxInstances) + " primitives");
        }
        Instance instance;
        instance.primitive = sceneIndex;
        instance.node = nodeIndex;
        instance.worldFromLocal = glm::mat4(world);
        instance.flipWinding = flipped;
        mScene.instances.push_back(instance);
    }
    return true;
}

bool SceneBuilder::placeCamera(int nodeIndex, const glm::dmat4& world) {
    const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
    const tinygltf::Camera& source = mModel.cameras[std::size_t(node.camera)];
    const std::string element = indexed("cameras", node.camera);
    if (source.type != "perspective") {
        warn(element, "camera type '" + source.type + "' is not supported; skipped");
        return true;
    }
    // Cameras ignore scale (glTF 2.0 section 3.10.1): orthonormalize, keeping -Z and +Y.
    const glm::dvec3 back = glm::dvec3(world[2]);
    const glm::dvec3 up = glm::dvec3(world[1]);
    const double backLength = glm::length(back);
    const glm::dvec3 z = back / backLength;
    const glm::dvec3 yRaw = up - glm::dot(up, z) * z;
    const double yLength = glm::length(yRaw);
    if (!(backLength > 1e-12) || !(yLength > 1e-12 * glm::length(up)) || !(yLength > 0.0)) {
        return fail(indexed("nodes", nodeIndex),
                "the transform of " + element + " is singular");
    }
    const glm::dvec3 y = yRaw / yLength;
    const glm::dvec3 x = glm::cross(y, z);
    Camera camera;
    camera.name = !source.name.empty() ? source.name
                  : !node.name.empty() ? node.name
                                       : element;
    camera.worldFromCamera = glm::mat4(glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0),
            glm::dvec4(z, 0.0), world[3]));
    camera.yfov = float(source.perspective.yfov);
    camera.znear = float(source.perspective.znear);
    camera.zfar = float(source.perspective.zfar);
    mScene.cameras.push_back(std::move(camera));
    return true;
}

bool SceneBuilder::placeLight(int nodeIndex, const glm::dmat4& world) {
    const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) return true;
    const std::string element = indexed("nodes", nodeIndex);
    const tinygltf::Value& value = ext->second;
    if (!value.IsObject() || !value.Has("light") || !value.Get("light").IsInt()) {
        return fail(element, "KHR_lights_punctual.light is not a light index");
    }
    const int index = value.Get("light").GetNumberAsInt();
    if (index < 0 || std::size_t(index) >= mModel.lights.size()) {
        return fail(element, doesNotExist("KHR_lights_punctual.light", index,
                                     mModel.lights.size(), "lights"));
    }
    const tinygltf::Light& source = mModel.lights[std::size_t(index)];
    Light light;
    light.name = !source.name.empty() ? source.name
                 : !node.name.empty() ? node.name
                                      : "KHR_lights_punctual." + indexed("lights", index);
    light.type = source.type == "spot"          ? LightType::Spot
                 : source.type == "directional" ? LightType::Directional
                                                : LightType::Point;
    light.position = glm::vec3(world[3]);
    const glm::dvec3 direction = -glm::dvec3(world[2]);
    const double length = glm::length(direction);
    if (light.type != LightType::Point && !(length > 1e-12)) {
        return fail(element, "the transform is singular, so the light has no direction");
    }
    if (length > 1e-12) light.direction = glm::vec3(direction / length);
    if (source.color.size() == 3) {
        light.color = glm::vec3(source.color[0], source.color[1], source.color[2]);
    }
    light.intensity = float(source.intensity);
    light.range = float(source.range);
    if (light.type == LightType::Spot) {
        light.innerConeAngle = float(source.spot.innerConeAngle);
        light.outerConeAngle = float(source.spot.outerConeAngle);
    }
    mScene.lights.push_back(std::move(light));
    return true;
}

} // namespace gi::scene::gltf
