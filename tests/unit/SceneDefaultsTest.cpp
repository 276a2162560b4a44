// The defaults a scene without lights or cameras gets (scene/SceneDefaults.h): the survey's
// interior / object classification on scenes built in code (rays cast by Embree, as the
// program casts them), the light and camera each kind gets, and finite defaults for empty and
// degenerate scenes. No change to scenes that bring their own.
#include "scene/SceneDefaults.h"

#include "TestScenes.h"
#include "reference/EmbreeRayCaster.h"
#include "scene/SceneSurvey.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gi::scene {
namespace {

// Values computed in float from metre-scale inputs.
constexpr float kEps = 1e-4f;

// A quad p0..p3 whose front faces `facing`.
void addQuad(Primitive& p, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
        glm::vec3 facing) {
    const auto base = std::uint32_t(p.positions.size());
    const glm::vec3 normal = glm::normalize(facing);
    for (const glm::vec3& corner : {p0, p1, p2, p3}) {
        p.positions.push_back(corner);
        p.normals.push_back(normal);
        p.localBounds.extend(corner);
    }
    const bool counterClockwise = glm::dot(glm::cross(p1 - p0, p2 - p0), facing) > 0.0f;
    if (counterClockwise) {
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    } else {
        p.indices.insert(p.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
}

// The six faces of the box lo..hi, their fronts facing into the box or out of it.
Primitive box(glm::vec3 lo, glm::vec3 hi, bool inward) {
    Primitive p;
    const float sign = inward ? -1.0f : 1.0f;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int end = 0; end < 2; ++end) {
            glm::vec3 corners[4];
            const float uv[4][2] = {{lo[u], lo[v]}, {hi[u], lo[v]}, {hi[u], hi[v]}, {lo[u], hi[v]}};
            for (int c = 0; c < 4; ++c) {
                corners[c][axis] = end ? hi[axis] : lo[axis];
                corners[c][u] = uv[c][0];
                corners[c][v] = uv[c][1];
            }
            glm::vec3 facing(0.0f);
            facing[axis] = sign * (end ? 1.0f : -1.0f);
            addQuad(p, corners[0], corners[1], corners[2], corners[3], facing);
        }
    }
    return p;
}

Primitive groundPlane(float halfSize) {
    Primitive p;
    addQuad(p, {-halfSize, 0, -halfSize}, {halfSize, 0, -halfSize}, {halfSize, 0, halfSize},
            {-halfSize, 0, halfSize}, {0, 1, 0});
    return p;
}

Scene sceneOf(std::initializer_list<Primitive> primitives) {
    Scene scene;
    for (const Primitive& p : primitives) test::addPrimitive(scene, p);
    return scene;
}

SceneSurvey survey(const Scene& scene) {
    std::string error;
    const auto state = reference::buildEmbreeState(scene, error);
    EXPECT_TRUE(state) << error;
    return surveyScene(defaultFramingBounds(scene), reference::EmbreeRayCaster(*state));
}

DefaultsReport addDefaults(Scene& scene) {
    std::string warning;
    DefaultsReport report = reference::addDefaultsFromGeometry(scene, warning);
    EXPECT_EQ(warning, "");
    return report;
}

glm::vec3 eyeOf(const Camera& camera) { return glm::vec3(camera.worldFromCamera[3]); }
glm::vec3 forwardOf(const Camera& camera) { return -glm::vec3(camera.worldFromCamera[2]); }

bool inside(const Aabb& box, const glm::vec3& p) {
    return glm::all(glm::greaterThan(p, box.min)) && glm::all(glm::lessThan(p, box.max));
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

TEST(SceneSurvey, OpenPlaneIsOutdoor) {
    const SceneSurvey s = survey(sceneOf({groundPlane(5.0f)}));
    EXPECT_EQ(s.kind, SceneKind::Object) << s.describe();
    EXPECT_GT(s.escapeFraction(), 0.9f) << "rays from the plane's centre leave it";
}

TEST(SceneSurvey, ClosedBoxSeenFromInsideIsInterior) {
    const SceneSurvey s = survey(sceneOf({box({-3, 0, -2}, {3, 3, 2}, true)}));
    EXPECT_EQ(s.kind, SceneKind::Interior) << s.describe();
    EXPECT_FLOAT_EQ(s.frontFraction(), 1.0f);
    ASSERT_TRUE(s.floorBelow && s.ceilingAbove);
    EXPECT_NEAR(*s.floorBelow, 1.5f, kEps);
    EXPECT_NEAR(*s.ceilingAbove, 1.5f, kEps);
}

TEST(SceneSurvey, ClosedBoxWithOutwardFacesIsAnObject) {
    const SceneSurvey s = survey(sceneOf({box({-1, -1, -1}, {1, 1, 1}, false)}));
    EXPECT_EQ(s.kind, SceneKind::Object) << s.describe();
    EXPECT_FLOAT_EQ(s.backFraction(), 1.0f);
}

TEST(SceneSurvey, ObjectOnAGroundIsOutdoor) {
    const SceneSurvey s =
            survey(sceneOf({groundPlane(5.0f), box({-0.5f, 0, -0.5f}, {0.5f, 2, 0.5f}, false)}));
    EXPECT_EQ(s.kind, SceneKind::Object) << s.describe();
}

TEST(SceneDefaults, InteriorGetsACeilingLightAndAnEyeHeightCameraAlongTheLongSide) {
    Scene scene = sceneOf({box({-5, 0, -2}, {5, 4, 2}, true)});
    const DefaultsReport report = addDefaults(scene);
    EXPECT_NE(report.lights.find("interior"), std::string::npos) << report.lights;
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_TRUE(light.isDefault);
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_NEAR(light.position.y, 3.6f, kEps) << "90% of the way from floor to ceiling";
    const float d = glm::length(light.position - scene.bounds.center());
    EXPECT_NEAR(light.intensity / (d * d), 1.0f, kEps) << "E = I / d^2 at the centre";

    ASSERT_EQ(scene.cameras.size(), 1u);
    const Camera& camera = scene.cameras[0];
    EXPECT_TRUE(camera.isDefault);
    EXPECT_TRUE(inside(scene.bounds, eyeOf(camera)));
    EXPECT_NEAR(eyeOf(camera).y, 1.7f, kEps) << "eye height above the floor";
    EXPECT_NEAR(std::abs(forwardOf(camera).x), 1.0f, kEps) << "looks along the 10 m side";
    EXPECT_GT(std::abs(eyeOf(camera).x), 3.0f) << "stands back towards a wall";
}

TEST(SceneDefaults, LowRoomPutsTheEyeHalfWayUp) {
    Scene scene = sceneOf({box({-2, 0, -2}, {2, 2, 2}, true)});
    addDefaults(scene);
    EXPECT_NEAR(eyeOf(scene.cameras[0]).y, 1.0f, kEps);
}

TEST(SceneDefaults, ObjectGetsASunFromTheCamerasSideAndAThreeQuarterView) {
    Scene scene = sceneOf({box({-1, -1, -1}, {1, 1, 1}, false)});
    const DefaultsReport report = addDefaults(scene);
    EXPECT_NE(report.lights.find("sun"), std::string::npos) << report.lights;
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& sun = scene.lights[0];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_NEAR(-sun.direction.y, std::sin(glm::radians(50.0f)), kEps) << "50 deg elevation";
    const glm::vec3 eye = eyeOf(scene.cameras[0]);
    EXPECT_GT(eye.x, 1.0f);
    EXPECT_GT(eye.z, 1.0f);
    EXPECT_NEAR(eye.y / glm::length(eye), std::sin(glm::radians(25.0f)), kEps);
    EXPECT_NEAR(glm::dot(glm::normalize(-eye), forwardOf(scene.cameras[0])), 1.0f, kEps);
    // The sun shines on the faces the camera sees: it comes from the camera's side.
    EXPECT_GT(glm::dot(-sun.direction, glm::normalize(eye)), 0.5f);
}

TEST(SceneDefaults, FlatBoardIsSeenFromTheSideItFaces) {
    Primitive board;
    addQuad(board, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, -1});
    Scene scene = sceneOf({board});
    addDefaults(scene);
    const glm::vec3 eye = eyeOf(scene.cameras[0]);
    EXPECT_LT(eye.z, -1.0f) << "the board faces -Z";
    EXPECT_GT(-eye.z / glm::length(eye), std::cos(glm::radians(25.0f))) << "seen squarely";
    EXPECT_GT(glm::dot(scene.lights[0].direction, glm::vec3(0, 0, 1)), 0.3f) << "lit from -Z";
}

TEST(SceneDefaults, EmptySceneGetsFiniteDefaults) {
    Scene scene;
    ASSERT_TRUE(scene.bounds.empty());
    addDefaults(scene);
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_GT(scene.lights[0].intensity, 0.0f);
    EXPECT_TRUE(finite(scene.cameras[0].worldFromCamera));
    EXPECT_GT(scene.cameras[0].zfar, scene.cameras[0].znear);
}

TEST(SceneDefaults, DegenerateBoundsGetFiniteDefaults) {
    for (const glm::vec3 point : {glm::vec3(0.0f), glm::vec3(1e17f, -3.0f, 2.0f)}) {
        Scene scene;
        scene.bounds.extend(point);
        const DefaultsReport report = scene::addDefaults(scene, NothingHitCaster());
        EXPECT_FALSE(report.camera.empty());
        EXPECT_TRUE(finite(scene.cameras[0].worldFromCamera));
        EXPECT_TRUE(std::isfinite(scene.lights[0].intensity));
        EXPECT_GT(scene.lights[0].intensity, 0.0f);
        EXPECT_NE(eyeOf(scene.cameras[0]), point);
    }
}

TEST(SceneDefaults, KeepsLightsAndCamerasTheSceneHas) {
    Scene scene = sceneOf({box({0, 0, 0}, {1, 1, 1}, false)});
    scene.lights.push_back(Light{});
    scene.cameras.push_back(Camera{});
    const DefaultsReport report = addDefaults(scene);
    EXPECT_EQ(report.lights, "");
    EXPECT_EQ(report.camera, "");
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.cameras.size(), 1u);
    EXPECT_FALSE(scene.lights[0].isDefault);
    EXPECT_FALSE(scene.cameras[0].isDefault);
}

} // namespace
} // namespace gi::scene
