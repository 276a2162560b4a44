// The one-plane voxel test both the cone trace and the atlas' voxel visibility use
// (shaders/common/voxel_plane.glsl), run on the GPU over hand-made voxels and segments.
#include "ComputeProbe.h"
#include "GpuTest.h"

#include <vector>

namespace gi::test {
namespace {

struct PlaneCase {
    glm::vec4 plane;   // xyz = mean normal, w = offset from the centre in voxel sizes
    glm::vec4 voxel;   // xyz = centre, w = edge size
    glm::vec4 a;       // xyz = segment start, w = tolerance (< 0: the shader's kPlaneTolerance)
    glm::vec4 b;       // xyz = segment end, w = level
};

struct PlaneResult {
    bool onePlane = false;           // voxelHoldsOnePlane(plane, level, false)
    bool onePlaneAnyLevel = false;   // voxelHoldsOnePlane(plane, level, true)
    bool crosses = false;            // segmentCrossesVoxelPlane(...)
};

constexpr float kDefaultTolerance = -1.0f;

// A unit voxel at the origin whose surface is the plane y = offset.
PlaneCase floorVoxel(float offset, glm::vec3 a, glm::vec3 b, float tolerance = kDefaultTolerance) {
    return {{0.0f, 1.0f, 0.0f, offset}, {0.0f, 0.0f, 0.0f, 1.0f}, {a, tolerance}, {b, 0.0f}};
}

class VoxelPlaneGpuTest : public GpuTest {
protected:
    std::vector<PlaneResult> run(const std::vector<PlaneCase>& cases) {
        std::string error;
        const std::vector<glm::ivec4> raw = runComputeProbe<glm::ivec4>(
                "tests/gpu/shaders/voxel_plane_probe.comp", cases, error);
        EXPECT_EQ(raw.size(), cases.size()) << error;
        std::vector<PlaneResult> results;
        for (const glm::ivec4& r : raw) results.push_back({r.x != 0, r.y != 0, r.z != 0});
        return results;
    }
};

TEST_F(VoxelPlaneGpuTest, SegmentThroughThePlaneIsBlocked) {
    const auto r = run({floorVoxel(0.0f, {0.0f, 0.3f, 0.0f}, {0.0f, -0.3f, 0.0f}),
                        floorVoxel(0.0f, {-0.4f, -0.2f, 0.1f}, {0.3f, 0.45f, -0.2f})});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_TRUE(r[0].crosses);
    EXPECT_TRUE(r[1].crosses) << "the direction does not matter";
}

TEST_F(VoxelPlaneGpuTest, SegmentBesideThePlanePasses) {
    const auto r = run({floorVoxel(0.0f, {-0.5f, 0.3f, 0.0f}, {0.5f, 0.3f, 0.0f}),
                        floorVoxel(0.0f, {-0.5f, -0.3f, 0.2f}, {0.5f, -0.2f, 0.2f}),
                        floorVoxel(0.0f, {0.0f, 0.45f, 0.0f}, {0.0f, 0.15f, 0.0f})});
    ASSERT_EQ(r.size(), 3u);
    EXPECT_FALSE(r[0].crosses) << "parallel, 0.3 voxel above";
    EXPECT_FALSE(r[1].crosses) << "slanted, below all the way";
    EXPECT_FALSE(r[2].crosses) << "stops 0.15 voxel short of the plane";
}

// kPlaneTolerance is 0.1 voxel sizes along the normal.
TEST_F(VoxelPlaneGpuTest, SegmentGrazingWithinToleranceIsBlocked) {
    const auto r = run({floorVoxel(0.0f, {-0.5f, 0.05f, 0.0f}, {0.5f, 0.05f, 0.0f}),
                        floorVoxel(0.0f, {-0.5f, -0.08f, 0.0f}, {0.5f, -0.08f, 0.3f}),
                        floorVoxel(0.0f, {0.0f, 0.4f, 0.0f}, {0.0f, 0.08f, 0.0f}),
                        floorVoxel(0.0f, {-0.5f, 0.12f, 0.0f}, {0.5f, 0.12f, 0.0f}),
                        floorVoxel(0.0f, {-0.5f, 0.05f, 0.0f}, {0.5f, 0.05f, 0.0f}, 0.01f)});
    ASSERT_EQ(r.size(), 5u);
    EXPECT_TRUE(r[0].crosses) << "parallel, 0.05 above";
    EXPECT_TRUE(r[1].crosses) << "parallel, 0.08 below";
    EXPECT_TRUE(r[2].crosses) << "stops 0.08 short";
    EXPECT_FALSE(r[3].crosses) << "parallel, 0.12 above: outside the tolerance";
    EXPECT_FALSE(r[4].crosses) << "0.05 above with a tolerance of 0.01";
}

TEST_F(VoxelPlaneGpuTest, PlaneOffsetAndVoxelPlacementScale) {
    // The plane x = 2 + 0.25 * 0.5 in a voxel of edge 0.5 centred at (2, 2, 2); a stored
    // normal a little shorter than 1 is the same plane.
    const glm::vec4 plane{0.95f, 0.0f, 0.0f, 0.25f};
    const glm::vec4 voxel{2.0f, 2.0f, 2.0f, 0.5f};
    auto segment = [&](glm::vec3 a, glm::vec3 b) {
        return PlaneCase{plane, voxel, {a, kDefaultTolerance}, {b, 0.0f}};
    };
    const auto r = run({segment({2.2f, 2.0f, 2.0f}, {2.05f, 2.1f, 2.0f}),
                        segment({2.0f, 1.9f, 2.0f}, {2.06f, 2.1f, 2.2f}),
                        segment({2.155f, 1.8f, 2.0f}, {2.155f, 2.2f, 2.0f}),
                        segment({2.205f, 1.8f, 2.0f}, {2.205f, 2.2f, 2.0f})});
    ASSERT_EQ(r.size(), 4u);
    EXPECT_TRUE(r[0].crosses);
    EXPECT_FALSE(r[1].crosses) << "ends 0.13 voxel sizes short of the plane";
    EXPECT_TRUE(r[2].crosses) << "parallel, 0.06 voxel sizes beside it";
    EXPECT_FALSE(r[3].crosses) << "parallel, 0.08 world units = 0.16 voxel sizes beside it";
}

// Only level 0's mean of unit normals can tell one plane from several; coarser levels store
// a normalised mean (propagate.comp), whose length says nothing.
TEST_F(VoxelPlaneGpuTest, OnlyLevelZeroTellsOnePlane) {
    auto voxelWith = [](glm::vec3 normal, int level) {
        return PlaneCase{{normal, 0.0f}, {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.2f, 0.0f, -1.0f},
                {0.0f, -0.2f, 0.0f, float(level)}};
    };
    const glm::vec3 corner{0.5f, 0.5f, 0.0f};        // floor and wall in equal parts: 0.71
    const glm::vec3 nearlyFlat{0.64f, 0.64f, 0.0f};  // 0.905
    const auto r = run({voxelWith({0.0f, 1.0f, 0.0f}, 0), voxelWith(corner, 0),
                        voxelWith(nearlyFlat, 0), voxelWith({0.0f, 1.0f, 0.0f}, 1),
                        voxelWith(corner, 2)});
    ASSERT_EQ(r.size(), 5u);
    EXPECT_TRUE(r[0].onePlane);
    EXPECT_FALSE(r[1].onePlane) << "two orientations shorten the mean";
    EXPECT_FALSE(r[1].onePlaneAnyLevel);
    EXPECT_TRUE(r[2].onePlane);
    EXPECT_FALSE(r[3].onePlane) << "a coarser level never says one plane";
    EXPECT_TRUE(r[3].onePlaneAnyLevel) << "unless asked to take its normal's length";
    EXPECT_FALSE(r[4].onePlaneAnyLevel);
}

} // namespace
} // namespace gi::test
