// The visibility march through the voxel occupancy (shaders/common/voxel_visibility.glsl), which
// converged atlas GI and VPL GI weight every sender by: segments past, along and through a
// voxelized cube's edge and a slab thinner than a voxel, on one scene-centred level whose
// placement the test checks puts the edge mid-voxel and both slab faces in one voxel.
#include "ComputeProbe.h"
#include "GpuTest.h"
#include "TestScenes.h"
#include "VoxelFrame.h"

#include "gl/Shared.h"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

namespace gi::test {
namespace {

// The six outward-facing faces of the box [lo, hi], counter-clockwise seen from outside.
scene::Primitive axisBox(glm::vec3 lo, glm::vec3 hi) {
    scene::Primitive p;
    const glm::vec3 corner[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z},
            {lo.x, hi.y, hi.z}};
    struct Face {
        int a, b, c, d;
        glm::vec3 normal;
    };
    const Face faces[6] = {{1, 2, 6, 5, {1, 0, 0}}, {0, 4, 7, 3, {-1, 0, 0}},
            {3, 7, 6, 2, {0, 1, 0}}, {0, 1, 5, 4, {0, -1, 0}}, {4, 5, 6, 7, {0, 0, 1}},
            {0, 3, 2, 1, {0, 0, -1}}};
    for (const Face& f : faces) {
        const auto base = std::uint32_t(p.positions.size());
        for (int v : {f.a, f.b, f.c, f.d}) {
            p.positions.push_back(corner[v]);
            p.normals.push_back(f.normal);
        }
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    return p;
}

struct SegmentCase {
    glm::vec4 receiver, receiverNormal, sender, senderNormal;
};

// A segment from `from` to `to` whose ends face each other.
SegmentCase segment(glm::vec3 from, glm::vec3 to) {
    const glm::vec3 dir = glm::normalize(to - from);
    return {glm::vec4(from, 0.0f), glm::vec4(dir, 0.0f), glm::vec4(to, 0.0f),
            glm::vec4(-dir, 0.0f)};
}

// Where p lies within its voxel of level 0, in voxel sizes from the voxel's lower corner.
glm::vec3 withinVoxel(const voxel::CascadeVolume& volume, glm::vec3 p) {
    const glm::vec3 local = (p - volume.origin(0)) / volume.voxelSize(0);
    return local - glm::floor(local);
}

class VoxelVisibilityGpuTest : public GpuTest {};

// Runs the cases of both tests below in the lit cascade of voxel GI, whose voxels of several
// surfaces block by their coverage, or in the occupancy the atlas' and the VPLs' marches walk
// (projectedAreas), where they block by the surfaces' area projected across the segment.
void edgeAndSlabCases(bool projectedAreas) {
    scene::Scene scene;
    scene.materials.resize(1);
    addPrimitive(scene, horizontalSquare(1.0f, -1.0f));
    addPrimitive(scene, horizontalSquare(1.0f, 1.0f));
    const float h = 0.31f, slabLo = 0.49f, slabHi = 0.53f;
    addPrimitive(scene, axisBox(glm::vec3(-h), glm::vec3(h)));
    addPrimitive(scene, axisBox({slabLo, -0.5f, -0.5f}, {slabHi, 0.5f, 0.5f}));
    scene.cameras.push_back(lookAtCamera({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 60.0f));

    Settings settings = thesisAllocation();
    settings.voxel.levels = 1;
    settings.voxel.resolution = 32;
    settings.voxel.sceneCentred = true;
    VoxelFrame frame(scene, settings, {16, 16});
    // The occupancy VPL GI marches (FrameRenderer::updateOccupancy), on the same level.
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    ASSERT_TRUE(renderer.setMode(render::GiMode::Vpl, error)) << error;
    gl::GpuProfiler profiler;
    renderer.render(scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds), {16, 16},
            render::OutputComponent::Final, profiler);
    ASSERT_NE(renderer.occupancyManager(), nullptr);
    const voxel::VoxelizationManager& manager =
            projectedAreas ? *renderer.occupancyManager() : frame.manager();
    const voxel::CascadeVolume& volume = manager.volume();
    ASSERT_EQ(volume.voxelSize(0), frame.manager().volume().voxelSize(0));
    const float size = volume.voxelSize(0);
    const glm::vec3 edge(h, 0.03f, h);   // on the cube's (+x, +z) vertical edge
    const glm::vec3 inVoxel = withinVoxel(volume, edge);
    ASSERT_GT(std::min(inVoxel.x, inVoxel.z), 0.3f) << "the edge runs through its voxel's middle";
    ASSERT_LT(std::max(inVoxel.x, inVoxel.z), 0.7f) << "the edge runs through its voxel's middle";
    ASSERT_LT(withinVoxel(volume, glm::vec3(slabLo)).x, withinVoxel(volume, glm::vec3(slabHi)).x)
            << "the slab's faces share a voxel";
    ASSERT_LT(slabHi - slabLo, size);

    const gi::OccupancyVolume occupancy = manager.occupancy();
    occupancy.bind();

    const glm::vec3 out = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));      // off the edge
    const glm::vec3 along = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f));   // past it
    const glm::vec3 slabLine(0.0f, 0.1f, 0.1f);
    const glm::vec3 slabCentre(0.5f * (slabLo + slabHi), 0.1f, 0.1f);
    const glm::vec3 slant = glm::normalize(glm::vec3(1.0f, 0.4f, 0.8f));
    const std::vector<SegmentCase> cases = {
            // Parallel to the edge's diagonal, a quarter voxel outside it, 15 cm either way:
            // through the edge's voxel, and a voxel or more out from the faces' voxels.
            segment(edge + out * (0.25f * size) - along * 0.15f,
                    edge + out * (0.25f * size) + along * 0.15f),
            // Into the cube across its edge.
            segment(edge + out * 0.5f, edge - out * (0.5f * h)),
            // Through the middle of the cube's -x face.
            segment({-0.6f, 0.03f, 0.02f}, {0.0f, 0.03f, 0.02f}),
            // Through the slab, whose two faces share a voxel.
            segment(slabLine + glm::vec3(0.35f, 0.0f, 0.0f),
                    slabLine + glm::vec3(0.8f, 0.0f, 0.0f)),
            // Beside everything.
            segment({-0.8f, 0.6f, 0.6f}, {0.8f, 0.6f, 0.6f}),
            // Across the slab at a slant, through several of its voxels.
            segment(slabCentre - slant * 0.2f, slabCentre + slant * 0.2f),
            // Along the cube's +x face a fifth of a voxel outside it and on past the edge:
            // through the edge's voxel beside the face, where the edge's mean plane lies.
            segment({h + 0.2f * size, 0.03f, -0.2f}, {h + 0.2f * size, 0.03f, h + 0.2f}),
            // A fifth of a voxel inside that face, from in front of the +z face: into the cube
            // through the edge's voxel.
            segment({h - 0.2f * size, 0.03f, h + 0.2f}, {h - 0.2f * size, 0.03f, -0.2f}),
    };
    error.clear();
    const std::vector<glm::vec4> r = runComputeProbe<glm::vec4>(
            "tests/gpu/shaders/voxel_visibility_probe.comp", cases, error);
    ASSERT_EQ(r.size(), cases.size()) << error;
    EXPECT_EQ(r[0].x, 1.0f) << "a segment passing outside the cube's edge is not blocked";
    EXPECT_LT(r[1].x, 0.05f) << "a segment into the cube across its edge is blocked";
    EXPECT_LT(r[2].x, 0.05f) << "a segment through the cube's -x face is blocked";
    EXPECT_LT(r[3].x, 0.05f) << "a slab thinner than a voxel blocks what crosses it";
    EXPECT_EQ(r[4].x, 1.0f) << "a segment beside everything is not blocked";
    EXPECT_LT(r[5].x, 0.05f) << "a slab blocks what crosses it at a slant";
    // Only the occupancy keeps its edge voxels' faces; voxel GI's cascade, which no march
    // walks, meets them at their mean plane.
    if (projectedAreas) {
        EXPECT_EQ(r[6].x, 1.0f) << "a segment grazing a face past the cube's edge is not blocked";
    } else {
        EXPECT_LT(r[6].x, 0.05f) << "the edge's mean plane blocks a segment grazing its face";
    }
    EXPECT_LT(r[7].x, 0.05f) << "a segment entering the cube through its edge's voxel is blocked";
}

// A cube of half-size 0.31 at the origin and a 4 cm slab at x = 0.49..0.53, inside two squares
// at y = +-1 that fix the bounds to [-1, 1]^3. On one scene-centred level of 32^3 (the bounds
// and a margin: 6.9 cm voxels) the cube's vertical edges run through the middle of their voxels,
// each holding two faces in equal parts, and both big faces of the slab share one voxel column.
TEST_F(VoxelVisibilityGpuTest, EdgeVoxelsBlockOnlyWhatCrossesTheEdgeAndSlabsStillBlock) {
    if (!mContext) GTEST_SKIP();
    edgeAndSlabCases(false);
}

// The same in the occupancy the atlas' and the VPLs' marches walk, where a voxel of several
// surfaces blocks by its surfaces' area projected across the segment.
TEST_F(VoxelVisibilityGpuTest, ProjectedCoverageBlocksEdgesAndSlabsAlike) {
    if (!mContext) GTEST_SKIP();
    edgeAndSlabCases(true);
}

} // namespace
} // namespace gi::test
