#include "TestScenes.h"

#include "GpuTest.h"

#include "reference/EmbreeRayCaster.h"
#include "scene/GltfLoader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gi::test {

scene::Primitive horizontalSquare(float halfSize, float y) {
    scene::Primitive p;
    p.positions = {{-halfSize, y, -halfSize}, {halfSize, y, -halfSize}, {halfSize, y, halfSize},
            {-halfSize, y, halfSize}};
    p.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    p.indices = {0, 2, 1, 0, 3, 2};   // counter-clockwise seen from +Y
    p.material = 0;
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    return p;
}

scene::Primitive downwardSquare(float halfSize, float y, const glm::vec2& centre, int material) {
    scene::Primitive p = horizontalSquare(halfSize, y);
    p.indices = {0, 1, 2, 0, 2, 3};   // counter-clockwise seen from -Y
    p.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
    p.material = material;
    p.localBounds = {};
    for (glm::vec3& v : p.positions) {
        v += glm::vec3(centre.x, 0.0f, centre.y);
        p.localBounds.extend(v);
    }
    return p;
}

void addPrimitive(scene::Scene& scene, scene::Primitive primitive) {
    scene::Instance instance;
    instance.primitive = int(scene.primitives.size());
    scene.bounds.extend(primitive.localBounds);
    scene.primitives.push_back(std::move(primitive));
    scene.instances.push_back(instance);
}

scene::Scene floorUnderLamp(float lampHalf, float lampHeight, const glm::vec2& lampCentre,
        float emission, const glm::vec3& eye) {
    scene::Scene scene;
    scene::Material grey, lamp;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    lamp.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    lamp.emissiveFactor = glm::vec3(emission);
    scene.materials = {grey, lamp};
    addPrimitive(scene, horizontalSquare(1.0f, 0.0f));
    addPrimitive(scene, downwardSquare(lampHalf, lampHeight, lampCentre, 1));
    scene.cameras.push_back(lookAtCamera(eye, {0.0f, 0.0f, 0.0f}, 50.0f));
    return scene;
}

scene::Scene floorWithPlate(float plateHalf, float plateHeight) {
    scene::Scene scene;
    scene::Material grey, black;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    black.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    black.doubleSided = true;
    scene.materials = {grey, black};
    addPrimitive(scene, horizontalSquare(1.0f, 0.0f));
    scene::Primitive plate = horizontalSquare(plateHalf, plateHeight);
    plate.material = 1;
    addPrimitive(scene, plate);
    scene.cameras.push_back(lookAtCamera({0.0f, 0.3f, 2.2f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    return scene;
}

scene::Camera lookAtCamera(const glm::vec3& eye, const glm::vec3& target, float yfovDegrees) {
    scene::Camera camera;
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 up = std::abs(forward.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f)
                                                     : glm::vec3(0.0f, 1.0f, 0.0f);
    camera.worldFromCamera = glm::inverse(glm::lookAt(eye, target, up));
    camera.yfov = glm::radians(yfovDegrees);
    return camera;
}

scene::Scene loadTestScene(const std::string& path) {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_TRUE(scene::loadGltf(!path.empty() && path[0] == '/' ? path : sourcePath(path), scene,
            error, warnings)) << error;
    addDefaults(scene);
    return scene;
}

void addDefaults(scene::Scene& scene) {
    std::string warning;
    reference::addDefaultsFromGeometry(scene, warning);
    EXPECT_EQ(warning, "");
}

scene::Scene loadCornellBox() {
    return loadTestScene("assets/cornell_box/cornell_box.gltf");
}

} // namespace gi::test
