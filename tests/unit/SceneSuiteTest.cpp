// The accuracy scene suite (assets/scene_suite, written by make_scene_suite.py): every file
// loads with its own cameras and lights, and each one is what its name claims. Closure and
// sunlight are checked by casting rays against the loaded triangles.
#include "TestScenes.h"

#include "core/Settings.h"
#include "render/ResourcePlan.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace gi::test {
namespace {

const char* const kSuite[] = {"cornell_classic", "cornell_double_sided", "cornell_glossy",
        "cornell_low_light",
        "cornell_x10", "cornell_spot", "cornell_open_front_sun", "two_rooms_thin_wall",
        "closed_white_box"};

scene::Scene loadSuiteScene(const std::string& name) {
    return loadTestScene("assets/scene_suite/" + name + ".gltf");
}

glm::vec3 cameraPosition(const scene::Camera& camera) {
    return glm::vec3(camera.worldFromCamera[3]);
}

const scene::Light& onlyLight(const scene::Scene& scene) {
    EXPECT_EQ(scene.lights.size(), 1u);
    return scene.lights.front();
}

// World-space triangles of every instance, with their material.
struct Triangle {
    glm::dvec3 a, b, c;
    int material = -1;
};

std::vector<Triangle> worldTriangles(const scene::Scene& scene) {
    std::vector<Triangle> triangles;
    for (const scene::Instance& instance : scene.instances) {
        const scene::Primitive& p = scene.primitives[std::size_t(instance.primitive)];
        auto world = [&](std::uint32_t i) {
            return glm::dvec3(instance.worldFromLocal * glm::vec4(p.positions[i], 1.0f));
        };
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            triangles.push_back({world(p.indices[t]), world(p.indices[t + 1]),
                    world(p.indices[t + 2]), p.material});
        }
    }
    return triangles;
}

struct Hit {
    glm::dvec3 point;
    bool frontFacing = false;  // the ray meets the side its counter-clockwise winding faces
    int material = -1;
};

// The nearest triangle along the ray (Moller-Trumbore), or nothing when the ray escapes.
std::optional<Hit> castRay(const std::vector<Triangle>& triangles, const glm::dvec3& origin,
        const glm::dvec3& dir) {
    std::optional<Hit> nearest;
    double nearestT = 1e30;
    for (const Triangle& tri : triangles) {
        const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
        const glm::dvec3 p = glm::cross(dir, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-15) continue;
        const glm::dvec3 s = origin - tri.a;
        const double u = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(dir, q) / det;
        const double t = glm::dot(e2, q) / det;
        const double eps = 1e-9;
        if (u < -eps || v < -eps || u + v > 1.0 + eps || t <= 1e-7 || t >= nearestT) continue;
        nearestT = t;
        nearest = Hit{origin + t * dir, glm::dot(glm::cross(e1, e2), dir) < 0.0, tri.material};
    }
    return nearest;
}

// n directions spread evenly over the sphere (a Fibonacci lattice, none along an axis).
std::vector<glm::dvec3> sphereDirections(int n) {
    std::vector<glm::dvec3> dirs;
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - (double(i) + 0.5) * 2.0 / double(n);
        const double r = std::sqrt(1.0 - y * y);
        dirs.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
    }
    return dirs;
}

// Every ray from `origin` meets a surface facing it inside `room` (a closed room seen from
// within: no ray escapes, none reaches past the room's walls).
void expectClosedAround(const std::vector<Triangle>& triangles, const glm::dvec3& origin,
        const scene::Aabb& room, const std::string& what) {
    const double eps = 1e-4;
    int escaped = 0, backFacing = 0, outside = 0;
    for (const glm::dvec3& dir : sphereDirections(2000)) {
        const std::optional<Hit> hit = castRay(triangles, origin, dir);
        if (!hit) {
            ++escaped;
            continue;
        }
        backFacing += hit->frontFacing ? 0 : 1;
        const glm::dvec3 lo = glm::dvec3(room.min) - eps, hi = glm::dvec3(room.max) + eps;
        outside += glm::all(glm::greaterThanEqual(hit->point, lo)) &&
                                   glm::all(glm::lessThanEqual(hit->point, hi))
                           ? 0
                           : 1;
    }
    EXPECT_EQ(escaped, 0) << what << ": rays that leave the scene";
    EXPECT_EQ(backFacing, 0) << what << ": rays that meet the back of a surface";
    EXPECT_EQ(outside, 0) << what << ": rays that end outside the room";
}

scene::Aabb worldBoundsOfMaterial(const scene::Scene& scene, const std::string& name) {
    scene::Aabb bounds;
    for (const Triangle& tri : worldTriangles(scene)) {
        if (tri.material >= 0 && scene.materials[std::size_t(tri.material)].name == name) {
            for (const glm::dvec3& p : {tri.a, tri.b, tri.c}) bounds.extend(glm::vec3(p));
        }
    }
    return bounds;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance, const char* what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << what << " axis " << i;
}

TEST(SceneSuite, EveryFileCarriesItsOwnCamerasAndLights) {
    for (const char* name : kSuite) {
        SCOPED_TRACE(name);
        const scene::Scene scene = loadSuiteScene(name);
        ASSERT_FALSE(scene.cameras.empty());
        ASSERT_FALSE(scene.lights.empty());
        for (const scene::Camera& camera : scene.cameras) EXPECT_FALSE(camera.isDefault);
        for (const scene::Light& light : scene.lights) {
            EXPECT_FALSE(light.isDefault);
            EXPECT_GT(light.intensity, 0.0f);
        }
        EXPECT_GT(scene.triangleCount(), 0u);
    }
}

TEST(SceneSuite, ClassicIsTheCornellBox) {
    const scene::Scene box = loadCornellBox();
    const scene::Scene classic = loadSuiteScene("cornell_classic");
    EXPECT_EQ(classic.triangleCount(), box.triangleCount());
    expectNear(classic.bounds.min, box.bounds.min, 0.0f, "bounds min");
    expectNear(classic.bounds.max, box.bounds.max, 0.0f, "bounds max");
    ASSERT_EQ(classic.materials.size(), box.materials.size());
    for (std::size_t i = 0; i < box.materials.size(); ++i) {
        EXPECT_EQ(classic.materials[i].baseColorFactor, box.materials[i].baseColorFactor);
    }
    EXPECT_EQ(onlyLight(classic), onlyLight(box));
    ASSERT_EQ(classic.cameras.size(), 1u);
    EXPECT_EQ(classic.cameras[0].worldFromCamera, box.cameras[0].worldFromCamera);
    EXPECT_EQ(classic.cameras[0].yfov, box.cameras[0].yfov);
}

TEST(SceneSuite, DoubleSidedHasTheFlagAndTexcoordsEverywhere) {
    const scene::Scene box = loadCornellBox();
    const scene::Scene scene = loadSuiteScene("cornell_double_sided");
    ASSERT_FALSE(scene.materials.empty());
    for (const scene::Material& material : scene.materials) {
        EXPECT_TRUE(material.doubleSided) << material.name;
    }
    for (const scene::Primitive& primitive : scene.primitives) {
        EXPECT_EQ(primitive.texcoords0.size(), primitive.positions.size());
    }
    EXPECT_EQ(scene.triangleCount(), box.triangleCount());
    expectNear(scene.bounds.max, box.bounds.max, 0.0f, "bounds max");
    EXPECT_EQ(onlyLight(scene), onlyLight(box));
}

TEST(SceneSuite, GlossyIsTheClassicBoxWithARoughMetalTallBlock) {
    const scene::Scene classic = loadSuiteScene("cornell_classic");
    const scene::Scene scene = loadSuiteScene("cornell_glossy");
    EXPECT_EQ(scene.triangleCount(), classic.triangleCount());
    expectNear(scene.bounds.max, classic.bounds.max, 0.0f, "bounds max");
    EXPECT_EQ(onlyLight(scene), onlyLight(classic));
    int metals = 0;
    for (const scene::Primitive& primitive : scene.primitives) {
        ASSERT_GE(primitive.material, 0);
        const scene::Material& m = scene.materials[std::size_t(primitive.material)];
        if (m.metallicFactor == 0.0f) {
            EXPECT_EQ(m.roughnessFactor, 1.0f) << m.name;
            continue;
        }
        ++metals;
        EXPECT_EQ(m.metallicFactor, 1.0f);
        EXPECT_FLOAT_EQ(m.roughnessFactor, 0.3f);
        // The tall block: the primitive reaching highest but the room's.
        EXPECT_NEAR(primitive.localBounds.max.y, 0.33f, 0.01f);
    }
    EXPECT_EQ(metals, 1);
}

TEST(SceneSuite, LowLightHangsATenthOfTheBoxHeightUnderTheCeiling) {
    const scene::Scene box = loadCornellBox();
    const scene::Scene scene = loadSuiteScene("cornell_low_light");
    const scene::Light& light = onlyLight(scene);
    EXPECT_EQ(light.type, scene::LightType::Point);
    EXPECT_NEAR(light.position.y, scene.bounds.max.y - 0.1f * scene.bounds.size().y, 1e-5f);
    EXPECT_EQ(light.position.x, onlyLight(box).position.x);
    EXPECT_EQ(light.position.z, onlyLight(box).position.z);
    EXPECT_EQ(light.intensity, onlyLight(box).intensity);
}

TEST(SceneSuite, X10IsTheWholeBoxTenTimesLargerWithTheSameRadiance) {
    const scene::Scene box = loadCornellBox();
    const scene::Scene scene = loadSuiteScene("cornell_x10");
    expectNear(scene.bounds.min, 10.0f * box.bounds.min, 1e-5f, "bounds min");
    expectNear(scene.bounds.max, 10.0f * box.bounds.max, 1e-5f, "bounds max");
    const scene::Light& light = onlyLight(scene);
    expectNear(light.position, 10.0f * onlyLight(box).position, 1e-5f, "light");
    // I / d^2 stays the same: x100 intensity at x10 distances.
    EXPECT_NEAR(light.intensity, 100.0f * onlyLight(box).intensity, 1e-4f);
    expectNear(cameraPosition(scene.cameras[0]), 10.0f * cameraPosition(box.cameras[0]), 1e-5f,
            "camera");
    EXPECT_EQ(scene.cameras[0].yfov, box.cameras[0].yfov);
}

TEST(SceneSuite, SpotPointsDownFromUnderTheCeilingOverTheWholeFloor) {
    const scene::Scene scene = loadSuiteScene("cornell_spot");
    const scene::Light& spot = onlyLight(scene);
    ASSERT_EQ(spot.type, scene::LightType::Spot);
    expectNear(spot.direction, glm::vec3(0.0f, -1.0f, 0.0f), 1e-6f, "direction");
    EXPECT_GT(spot.position.y, 0.9f * scene.bounds.max.y);
    EXPECT_LT(spot.position.y, scene.bounds.max.y);
    EXPECT_LT(spot.innerConeAngle, spot.outerConeAngle);
    // Every corner of the floor lies inside the outer cone, the middle of each floor edge
    // inside the inner one (full strength).
    const scene::Aabb& b = scene.bounds;
    auto offAxis = [&](float x, float z) {
        const glm::vec3 to = glm::normalize(glm::vec3(x, b.min.y, z) - spot.position);
        return std::acos(glm::dot(to, spot.direction));
    };
    const glm::vec3 c = b.center();
    for (float x : {b.min.x, b.max.x}) {
        for (float z : {b.min.z, b.max.z}) EXPECT_LT(offAxis(x, z), spot.outerConeAngle);
        EXPECT_LT(offAxis(x, c.z), spot.innerConeAngle);
    }
    for (float z : {b.min.z, b.max.z}) EXPECT_LT(offAxis(c.x, z), spot.innerConeAngle);
}

TEST(SceneSuite, OpenFrontSunLightsTheFloorThroughTheFrontOnly) {
    const scene::Scene box = loadCornellBox();
    const scene::Scene scene = loadSuiteScene("cornell_open_front_sun");
    const scene::Light& sun = onlyLight(scene);
    ASSERT_EQ(sun.type, scene::LightType::Directional);
    // Ground reaches at least half a metre beyond the box on every side.
    EXPECT_LT(scene.bounds.min.x, box.bounds.min.x - 0.5f);
    EXPECT_GT(scene.bounds.max.x, box.bounds.max.x + 0.5f);
    EXPECT_LT(scene.bounds.min.z, box.bounds.min.z - 0.5f);
    EXPECT_GT(scene.bounds.max.z, box.bounds.max.z + 0.5f);
    EXPECT_EQ(scene.bounds.min.y, 0.0f);

    // Points on the box's floor and back wall that see the sun; each sunbeam must come in
    // through the open front (z = 0, within the box's width and height).
    const std::vector<Triangle> triangles = worldTriangles(scene);
    const glm::dvec3 toSun = -glm::dvec3(sun.direction);
    const glm::dvec3 lo(box.bounds.min), hi(box.bounds.max);
    int floorLit = 0, floorPoints = 0, wallLit = 0;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            const double u = (i + 0.5) / 10.0, v = (j + 0.5) / 10.0;
            const glm::dvec3 floor(glm::mix(lo.x, hi.x, u), 1e-6, glm::mix(lo.z, hi.z, v));
            const glm::dvec3 wall(glm::mix(lo.x, hi.x, u), glm::mix(lo.y, hi.y, v), lo.z + 1e-6);
            for (const glm::dvec3& p : {floor, wall}) {
                if (castRay(triangles, p, toSun)) continue;
                const glm::dvec3 entry = p + toSun * ((0.0 - p.z) / toSun.z);
                EXPECT_GE(entry.y, lo.y);
                EXPECT_LE(entry.y, hi.y) << "sunlight through the ceiling";
                EXPECT_GE(entry.x, lo.x - 1e-6);
                EXPECT_LE(entry.x, hi.x + 1e-6) << "sunlight through a wall";
                (p == floor ? floorLit : wallLit) += 1;
            }
            ++floorPoints;
        }
    }
    EXPECT_GT(floorLit, floorPoints / 3) << "the sun lights a good part of the floor";
    EXPECT_LT(floorLit, floorPoints) << "the blocks and walls cast shadows";
    EXPECT_GT(wallLit, 0) << "the sun reaches the back wall";
}

TEST(SceneSuite, ThinWallIsOneFinestVoxelOfTheAdaptivePlan) {
    const scene::Scene scene = loadSuiteScene("two_rooms_thin_wall");
    const scene::Aabb wall = worldBoundsOfMaterial(scene, "shared_wall");
    ASSERT_FALSE(wall.empty());
    Settings adaptive;
    adaptive.plan = PLAN_ADAPTIVE;
    const render::ResourcePlan plan = render::planResources(scene, scene.lights, adaptive,
            cameraPosition(scene.cameras[1]));
    const float voxel = plan.voxel.voxelSize(0);
    EXPECT_NEAR(wall.size().x, voxel, 1e-6f) << "the shared wall is one finest voxel thick";
    EXPECT_NEAR(wall.center().x, 0.0f, 1e-6f);
    // It fills the rooms' whole height and depth.
    EXPECT_EQ(wall.min.y, scene.bounds.min.y);
    EXPECT_EQ(wall.max.y, scene.bounds.max.y);
    EXPECT_EQ(wall.min.z, scene.bounds.min.z);
    EXPECT_EQ(wall.max.z, scene.bounds.max.z);

    const scene::Light& light = onlyLight(scene);
    EXPECT_EQ(light.type, scene::LightType::Point);
    EXPECT_LT(light.position.x, wall.min.x) << "the light is in the lit room (x < 0)";
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_LT(cameraPosition(scene.cameras[0]).x, wall.min.x) << "camera 0: the lit room";
    EXPECT_GT(cameraPosition(scene.cameras[1]).x, wall.max.x) << "camera 1: the dark room";
}

TEST(SceneSuite, BothRoomsAreClosedButForTheSharedWall) {
    const scene::Scene scene = loadSuiteScene("two_rooms_thin_wall");
    const scene::Aabb wall = worldBoundsOfMaterial(scene, "shared_wall");
    scene::Aabb litRoom = scene.bounds, darkRoom = scene.bounds;
    litRoom.max.x = wall.min.x;
    darkRoom.min.x = wall.max.x;
    const std::vector<Triangle> triangles = worldTriangles(scene);
    expectClosedAround(triangles, onlyLight(scene).position, litRoom, "from the light");
    expectClosedAround(triangles, cameraPosition(scene.cameras[0]), litRoom, "lit room camera");
    expectClosedAround(triangles, cameraPosition(scene.cameras[1]), darkRoom, "dark room camera");
}

TEST(SceneSuite, ClosedWhiteBoxIsClosedWhiteAndLitFromItsCentre) {
    const scene::Scene scene = loadSuiteScene("closed_white_box");
    for (const scene::Material& material : scene.materials) {
        const glm::vec4 c = material.baseColorFactor;
        EXPECT_EQ(c.r, c.g);
        EXPECT_EQ(c.g, c.b);
        EXPECT_GE(c.r, 0.7f) << material.name << " is white";
        EXPECT_EQ(material.baseColorTexture, -1);
    }
    const scene::Light& light = onlyLight(scene);
    EXPECT_EQ(light.type, scene::LightType::Point);
    expectNear(light.position, scene.bounds.center(), 1e-6f, "light at the centre");
    const std::vector<Triangle> triangles = worldTriangles(scene);
    expectClosedAround(triangles, light.position, scene.bounds, "from the light");
    expectClosedAround(triangles, cameraPosition(scene.cameras[0]), scene.bounds, "camera");
}

} // namespace
} // namespace gi::test
