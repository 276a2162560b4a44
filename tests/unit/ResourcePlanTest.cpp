// The resource plan (render/ResourcePlan.h) for the scenes users render: the Cornell box gets
// one scene-centred level of v^3, Sponza one of 128^3 at the finest voxel a cascade would
// have, the open-front box one of 128^3 at less than twice the voxel it asks for, and a
// cascade reaching all of it where one level would need more; the fixed plan
// reports the thesis' allocation as given; lights that cannot reach the scene are left out.
#include "render/ResourcePlan.h"
#include "Sponza.h"

#include "GpuTest.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gi::render {
namespace {

glm::vec3 startEye(const scene::Scene& scene) {
    return glm::vec3(scene.cameras.front().worldFromCamera[3]);
}

Settings adaptive(int resolution) {
    Settings s;
    s.plan = PLAN_ADAPTIVE;
    s.voxel.resolution = resolution;
    return s;
}

TEST(ResourcePlan, AdaptiveIsTheDefault) {
    EXPECT_EQ(Settings{}.plan, PLAN_ADAPTIVE);
}

TEST(ResourcePlan, CornellBoxIsOneSceneCentredLevel) {
    const scene::Scene box = test::loadCornellBox();
    const ResourcePlan plan = planResources(box, box.lights, adaptive(32), startEye(box));
    EXPECT_EQ(plan.voxel.levels, 1);
    EXPECT_TRUE(plan.voxel.sceneCentred);
    // The level holds the whole box (0.56 m) with snapping room, in voxels under 2 cm.
    EXPECT_GE(plan.voxel.finestExtent, 0.5592f);
    EXPECT_LT(plan.voxel.voxelSize(0), 0.02f);
    // Six faces of 16^3 + 8^3 + ... + 1 RGBA16F texels.
    const std::size_t pyramid =
            8u * 6u * (16u * 16u * 16u + 8u * 8u * 8u + 4u * 4u * 4u + 2u * 2u * 2u + 1u);
    const std::size_t distanceScratch = 2u * 32u * 32u * 32u;
    EXPECT_EQ(plan.voxelBytes(), 44u * 32u * 32u * 32u + pyramid + distanceScratch)
            << "32 bytes per voxel, 12 for injection's fixed-point flux sums, plus the radiance "
               "pyramid of the coarsest level and the empty-distance pass' two bytes per "
               "coarsest voxel";
    // The fixed thesis allocation: three camera-centred levels, the finest of which hold only
    // the air between the camera and the box.
    const Settings fixed = test::thesisAllocation();
    const ResourcePlan thesis = planResources(box, box.lights, fixed, startEye(box));
    EXPECT_EQ(thesis.voxel.levels, 3);
    EXPECT_FALSE(thesis.voxel.sceneCentred);
    EXPECT_GT(thesis.voxel.voxelSize(2), 4.0f * plan.voxel.voxelSize(0))
            << "the only level holding the box is much coarser than the adaptive one";
    EXPECT_EQ(thesis.voxelBytes(), 3u * 44u * 32u * 32u * 32u + pyramid + distanceScratch);
    // The atlas: about 1.9 m^2 of surface at half a voxel per texel.
    EXPECT_NEAR(plan.surfaceArea, 1.9, 0.3);
    EXPECT_GE(plan.atlasResolution, 128);
    EXPECT_LE(plan.atlasResolution, 384);
    EXPECT_EQ(plan.atlasResolution % 64, 0);
    EXPECT_EQ(thesis.atlasResolution, 1024);
    EXPECT_EQ(plan.lights.size(), 1u);
}

TEST(ResourcePlan, SponzaWithoutTheOneLevelIsACameraCascadeReachingAllOfIt) {
    VOXATLAS_SPONZA_OR_SKIP(path);
    const scene::Scene sponza = test::loadTestScene(path);
    Settings cascade = adaptive(32);
    cascade.voxel.oneLevelLimit = 0;
    const ResourcePlan plan = planResources(sponza, sponza.lights, cascade, startEye(sponza));
    const glm::vec3 size = sponza.bounds.size();
    const float shortest = std::min(size.x, std::min(size.y, size.z));
    const float longest = std::max(size.x, std::max(size.y, size.z));
    EXPECT_FALSE(plan.voxel.sceneCentred);
    EXPECT_TRUE(plan.voxel.clampCentre);
    // The coarsest level just reaches the far end from anywhere inside (twice the longest
    // side, with snapping slack); one level less at the shortest side / v would not.
    const float coarsest = plan.voxel.finestExtent * float(1 << (plan.voxel.levels - 1));
    EXPECT_NEAR(coarsest, 2.0f * longest * 1.1f, 1e-3f * longest);
    EXPECT_EQ(plan.voxel.levels, 4);
    EXPECT_LT(shortest * float(1 << (plan.voxel.levels - 2)), coarsest);
    // The slack of rounding the levels up went to finer voxels.
    EXPECT_LE(plan.voxel.voxelSize(0), shortest / 32.0f);
    EXPECT_GT(plan.voxel.voxelSize(0), 0.5f * shortest / 32.0f);
    // More levels than the Cornell box, and a larger atlas for 100x the surface.
    EXPECT_GT(plan.surfaceArea, 1000.0);
    EXPECT_GT(plan.atlasResolution, 256);
    // A finer voxel.size adds levels, never voxels per level.
    Settings finer = cascade;
    finer.voxel.size = plan.voxel.voxelSize(0) / 4.0f;
    const ResourcePlan fine = planResources(sponza, sponza.lights, finer, startEye(sponza));
    EXPECT_EQ(fine.voxel.levels, plan.voxel.levels + 2);
    EXPECT_EQ(fine.voxel.resolution, 32);
}

TEST(ResourcePlan, SponzaIsOneSceneCentredLevelAtTheCascadesFinestVoxel) {
    VOXATLAS_SPONZA_OR_SKIP(path);
    const scene::Scene sponza = test::loadTestScene(path);
    Settings cascadeSettings = adaptive(32);
    cascadeSettings.voxel.oneLevelLimit = 0;
    const ResourcePlan cascade =
            planResources(sponza, sponza.lights, cascadeSettings, startEye(sponza));
    const ResourcePlan plan = planResources(sponza, sponza.lights, adaptive(32), startEye(sponza));
    EXPECT_EQ(plan.voxel.levels, 1);
    EXPECT_TRUE(plan.voxel.sceneCentred);
    EXPECT_EQ(plan.voxel.resolution, 128);
    EXPECT_LE(plan.voxel.voxelSize(0), cascade.voxel.voxelSize(0) * 1.0001f);
    EXPECT_GT(plan.voxel.voxelSize(0), 0.5f * cascade.voxel.voxelSize(0));
    // The level covers the whole scene.
    const glm::vec3 size = sponza.bounds.size();
    EXPECT_GE(plan.voxel.finestExtent, std::max(size.x, std::max(size.y, size.z)));
    // Its raster keeps the cascade's size, v x voxel.multiplier pixels a side.
    EXPECT_EQ(plan.voxel.resolution * plan.voxel.multiplier, 32 * Settings{}.voxel.multiplier);
    const Settings applied = applyPlan(adaptive(32), plan);
    EXPECT_EQ(applied.voxel.resolution, 128);
    EXPECT_EQ(applied.voxel.levels, 1);
    EXPECT_EQ(applied.voxel.multiplier, plan.voxel.multiplier);
    // 64 cascade levels' worth of voxels: what one level at the finest voxel costs.
    EXPECT_GT(plan.voxelBytes(), 15 * cascade.voxelBytes());
    // A finest voxel one level of 128^3 cannot hold the scene at keeps the cascade.
    Settings finer = adaptive(32);
    finer.voxel.size = cascade.voxel.voxelSize(0) / 4.0f;
    const ResourcePlan fine = planResources(sponza, sponza.lights, finer, startEye(sponza));
    EXPECT_EQ(fine.voxel.levels, cascade.voxel.levels + 2);
    EXPECT_EQ(fine.voxel.resolution, 32);
    EXPECT_FALSE(fine.voxel.sceneCentred);
}

TEST(ResourcePlan, OneLevelWhereItIsNoLargerThanTheLimit) {
    const scene::Scene rooms = test::loadTestScene("assets/scene_suite/two_rooms_thin_wall.gltf");
    Settings s = adaptive(32);
    const float cascadeVoxel = [&] {
        s.voxel.oneLevelLimit = 0;
        return planResources(rooms, rooms.lights, s, startEye(rooms)).voxel.voxelSize(0);
    }();
    for (const int limit : {0, 16, 32, 64, 128}) {
        s.voxel.oneLevelLimit = limit;
        const ResourcePlan plan = planResources(rooms, rooms.lights, s, startEye(rooms));
        // The rooms need 64 voxels a side at the voxel their size asks for; a limit of 32
        // holds them at twice that voxel, the cascade's second level's (the next test).
        const bool one = limit >= 32;
        EXPECT_EQ(plan.voxel.levels, one ? 1 : 3) << "limit " << limit;
        EXPECT_EQ(plan.voxel.resolution, one ? std::min(limit, 64) : 32) << "limit " << limit;
        EXPECT_EQ(plan.voxel.multiplier, limit >= 64 ? 4 : limit == 32 ? 8 : 0)
                << "limit " << limit;
        if (limit == 32) EXPECT_LE(plan.voxel.voxelSize(0), 2.0f * cascadeVoxel * 1.0001f);
    }
}

// A scene the largest level the limit allows holds at up to twice the voxel its thickness
// asks for gets that level rather than a cascade: the open-front box (2.6 m of sunlit ground
// around a 0.56 m box) in 128^3 voxels of 2.2 cm instead of five levels of 32^3 whose finest
// (1.1 cm) holds 35 cm around the camera and whose third (4.4 cm) already holds the box's
// back; a finer voxel.size, which one level could hold only at more than twice its voxel,
// keeps the cascade.
TEST(ResourcePlan, OneLevelAtUpToTwiceTheVoxelBeforeACascade) {
    const scene::Scene box = test::loadTestScene("assets/scene_suite/cornell_open_front_sun.gltf");
    Settings s = adaptive(32);
    const glm::vec3 size = box.bounds.size();
    const float asked = std::min(size.x, std::min(size.y, size.z)) / 32.0f;
    const ResourcePlan plan = planResources(box, box.lights, s, startEye(box));
    EXPECT_EQ(plan.voxel.levels, 1);
    EXPECT_TRUE(plan.voxel.sceneCentred);
    EXPECT_EQ(plan.voxel.resolution, 128);
    EXPECT_GT(plan.voxel.voxelSize(0), asked) << "one level of 128^3 at the asked voxel fits";
    EXPECT_LE(plan.voxel.voxelSize(0), 2.0f * asked);
    EXPECT_GE(plan.voxel.finestExtent, std::max(size.x, std::max(size.y, size.z)));
    s.voxel.oneLevelLimit = 64;
    const ResourcePlan cascade = planResources(box, box.lights, s, startEye(box));
    EXPECT_EQ(cascade.voxel.levels, 5) << "64^3 would need more than twice the voxel";
    EXPECT_FALSE(cascade.voxel.sceneCentred);
    s.voxel.oneLevelLimit = 128;
    s.voxel.size = 0.5f * asked;
    const ResourcePlan finer = planResources(box, box.lights, s, startEye(box));
    EXPECT_GT(finer.voxel.levels, 1) << "128^3 would need more than twice the voxel";
}

TEST(ResourcePlan, ApplyWritesThePlanIntoTheSettings) {
    const scene::Scene box = test::loadCornellBox();
    const Settings requested = adaptive(64);
    const ResourcePlan plan = planResources(box, box.lights, requested, startEye(box));
    const Settings s = applyPlan(requested, plan);
    EXPECT_EQ(s.voxel.levels, 1);
    EXPECT_TRUE(s.voxel.sceneCentred);
    EXPECT_FLOAT_EQ(s.voxel.extent, plan.voxel.finestExtent);
    EXPECT_EQ(s.atlas.resolution, plan.atlasResolution);
    Settings fixed = test::thesisAllocation();
    fixed.voxel.levels = 5;
    const Settings unchanged = applyPlan(fixed, planResources(box, box.lights, fixed, startEye(box)));
    EXPECT_EQ(unchanged.voxel.levels, 5);
    EXPECT_EQ(unchanged.voxel.extent, 0.0f) << "fixed plans keep deriving the extent at run time";
}

TEST(ResourcePlan, InjectionHasFourLightPixelsPerFinestVoxel) {
    const scene::Scene box = test::loadCornellBox();
    const ResourcePlan plan = planResources(box, box.lights, adaptive(32), startEye(box));
    const glm::vec3 size = box.bounds.size();
    const float longest = std::max(size.x, std::max(size.y, size.z));
    const float lightPixel = longest / float(plan.voxel.injectResolution);
    EXPECT_LE(lightPixel, 0.25f * plan.voxel.voxelSize(0));
    EXPECT_GT(lightPixel, 0.225f * plan.voxel.voxelSize(0)) << "no more pixels than that";
    EXPECT_EQ(applyPlan(adaptive(32), plan).voxel.injectResolution, plan.voxel.injectResolution);
    // A resolution the user sets is kept; the fixed plan leaves 0, which means v (the thesis).
    Settings given = adaptive(32);
    given.voxel.injectResolution = 48;
    EXPECT_EQ(planResources(box, box.lights, given, startEye(box)).voxel.injectResolution, 48);
    const Settings fixed = test::thesisAllocation();
    const ResourcePlan thesis = planResources(box, box.lights, fixed, startEye(box));
    EXPECT_EQ(applyPlan(fixed, thesis).voxel.injectResolution, 0);
}

TEST(ResourcePlan, ConesAreNineteenOnTheAdaptivePlanAndTheThesisNineOnTheFixed) {
    const scene::Scene box = test::loadCornellBox();
    const Settings requested = adaptive(32);
    EXPECT_EQ(requested.voxel.cones, VOXEL_CONES_PLAN);
    EXPECT_EQ(applyPlan(requested, planResources(box, box.lights, requested, startEye(box)))
                      .voxel.cones,
            VOXEL_CONES_RINGS);
    const Settings fixed = test::thesisAllocation();
    EXPECT_EQ(applyPlan(fixed, planResources(box, box.lights, fixed, startEye(box))).voxel.cones,
            VOXEL_CONES_THESIS);
    // A set the user names is kept on either plan.
    Settings given = fixed;
    given.voxel.cones = VOXEL_CONES_RINGS;
    EXPECT_EQ(applyPlan(given, planResources(box, box.lights, given, startEye(box))).voxel.cones,
            VOXEL_CONES_RINGS);
    given = requested;
    given.voxel.cones = VOXEL_CONES_THESIS;
    EXPECT_EQ(applyPlan(given, planResources(box, box.lights, given, startEye(box))).voxel.cones,
            VOXEL_CONES_THESIS);
}

TEST(ResourcePlan, VoxelizationHasFourSamplesAPixelOnTheAdaptivePlanAndOneOnTheFixed) {
    const scene::Scene box = test::loadCornellBox();
    const auto samples = [&](const Settings& s) {
        const ResourcePlan plan = planResources(box, box.lights, s, startEye(box));
        EXPECT_EQ(applyPlan(s, plan).voxel.msaa, plan.voxel.msaa);
        return plan.voxel.msaa;
    };
    Settings requested = adaptive(32);
    EXPECT_EQ(requested.voxel.msaa, 0);
    EXPECT_EQ(samples(requested), 4);
    Settings fixed = test::thesisAllocation();
    EXPECT_EQ(samples(fixed), 1);
    // A count the user names is kept on either plan.
    fixed.voxel.msaa = 2;
    EXPECT_EQ(samples(fixed), 2);
    requested.voxel.msaa = 1;
    EXPECT_EQ(samples(requested), 1);
    EXPECT_NE(describePlan(planResources(box, box.lights, requested, startEye(box)))
                      .find("voxelized with 1 sample a raster pixel"),
            std::string::npos);
}

TEST(ResourcePlan, TheDescriptionNamesEachPlansConeSet) {
    const scene::Scene box = test::loadCornellBox();
    const Settings requested = adaptive(32);
    EXPECT_NE(describePlan(planResources(box, box.lights, requested, startEye(box)))
                      .find("19 diffuse cones (1 + 6 + 12) of 37.3 degrees"),
            std::string::npos);
    Settings fixed = test::thesisAllocation();
    EXPECT_NE(describePlan(planResources(box, box.lights, fixed, startEye(box)))
                      .find("9 diffuse cones (1 + 8) of 45 degrees"),
            std::string::npos);
    fixed.voxel.coneAngle = 30.0f;
    EXPECT_NE(describePlan(planResources(box, box.lights, fixed, startEye(box)))
                      .find("9 diffuse cones (1 + 8) of 30 degrees"),
            std::string::npos);
}

TEST(ResourcePlan, LightsThatCannotReachTheSceneAreLeftOut) {
    scene::Aabb room;
    room.extend(glm::vec3(0.0f));
    room.extend(glm::vec3(1.0f));
    scene::Light ceiling;
    ceiling.name = "ceiling";
    ceiling.position = glm::vec3(0.5f, 0.9f, 0.5f);
    scene::Light dark = ceiling;
    dark.name = "dark";
    dark.intensity = 0.0f;
    scene::Light away = ceiling;
    away.name = "away";
    away.type = scene::LightType::Spot;
    away.position = glm::vec3(0.5f, 3.0f, 0.5f);
    away.direction = glm::vec3(0.0f, 1.0f, 0.0f);   // points at the sky
    away.outerConeAngle = 0.3f;
    scene::Light down = away;
    down.name = "down";
    down.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    scene::Light faint = ceiling;
    faint.name = "faint";
    faint.position = glm::vec3(0.5f, 1000.0f, 0.5f);   // 1e-6 of the ceiling light's irradiance
    scene::Light sun;
    sun.name = "sun";
    sun.type = scene::LightType::Directional;
    std::vector<std::string> dropped;
    const std::vector<int> kept =
            lightsReaching({ceiling, dark, away, down, faint, sun}, room, kAdaptiveLightCutoff, &dropped);
    EXPECT_EQ(kept, (std::vector<int>{0, 3, 5}));
    ASSERT_EQ(dropped.size(), 3u);
    EXPECT_NE(dropped[0].find("dark: emits nothing"), std::string::npos);
    EXPECT_NE(dropped[1].find("away: its cone misses"), std::string::npos);
    EXPECT_NE(dropped[2].find("faint: under 0.0001"), std::string::npos);
    // Without a cutoff (fixed plans) only the lights that add nothing at all are left out.
    EXPECT_EQ(lightsReaching({ceiling, dark, away, down, faint, sun}, room, 0.0),
            (std::vector<int>{0, 3, 4, 5}));
    scene::Scene box = test::loadCornellBox();
    box.lights.push_back(dark);
    const ResourcePlan fixed =
            planResources(box, box.lights, test::thesisAllocation(), startEye(box));
    EXPECT_EQ(fixed.lights, (std::vector<int>{0}));
}

} // namespace
} // namespace gi::render
