// The resource plan (render/ResourcePlan.h) is what the renderer allocates: the voxel bytes
// `voxatlas info` reports for a plan are the voxel textures FrameRenderer holds in voxel mode,
// the atlas bytes its atlas layers in atlas mode, and only the active mode holds any. The
// renderer's report lists the storage actually allocated (gl/MemoryRegistry.h), so this compares
// the plan with what the GL was asked for.
#include "GpuTest.h"
#include "Sponza.h"
#include "TestScenes.h"

#include "gi/voxel/VoxelizationManager.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "render/FrameRenderer.h"

#include <gtest/gtest.h>

namespace gi::test {
namespace {

// Allocates voxel and then atlas GI for `scene` at `settings` and checks both against the plan.
// Bytes of the report's rows named like the plan's items (a plan item may stand for several
// rows: "voxel/static" for the cache's four volumes).
std::size_t plannedBytes(const std::vector<gl::MemoryItem>& report,
        const std::vector<gl::MemoryItem>& planned) {
    std::size_t total = 0;
    for (const gl::MemoryItem& item : planned) total += bytesWithPrefix(report, item.name);
    return total;
}

void expectAllocationMatchesPlan(const scene::Scene& scene, const Settings& settings) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    const render::ResourcePlan& plan = renderer.plan();
    EXPECT_EQ(bytesWithPrefix(renderer.memory(), "voxel/"), 0u) << "direct mode holds no GI";
    ASSERT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
    const std::vector<gl::MemoryItem> voxelMemory = renderer.memory();
    // The trace targets (voxel/trace...) scale with the output, not the plan: compare the
    // cascade's textures.
    EXPECT_EQ(plannedBytes(voxelMemory, plan.voxelMemory), plan.voxelBytes());
    EXPECT_EQ(bytesWithPrefix(voxelMemory, "atlas/"), 0u);
    const auto* voxels = dynamic_cast<const voxel::VoxelizationManager*>(renderer.technique());
    ASSERT_NE(voxels, nullptr);
    EXPECT_EQ(voxels->textures().levels, plan.voxel.levels);
    EXPECT_EQ(renderer.effectiveSettings().voxel.levels, plan.voxel.levels);
    ASSERT_TRUE(renderer.setMode(render::GiMode::Atlas, error)) << error;
    const std::vector<gl::MemoryItem> atlasMemory = renderer.memory();
    EXPECT_EQ(plannedBytes(atlasMemory, plan.atlasMemory), plan.atlasBytes());
    EXPECT_EQ(bytesWithPrefix(atlasMemory, "voxel/"), 0u) << "voxel GI released its cascade";
    // The plan counts the shadow maps; the small table of light matrices beside them is not
    // a budgeted resource.
    EXPECT_EQ(plannedBytes(atlasMemory, plan.shadowMemory), plan.shadowBytes());
}

class ResourcePlanGpuTest : public GpuTest {};

TEST_F(ResourcePlanGpuTest, CornellBoxAllocatesItsPlan) {
    const scene::Scene box = loadCornellBox();
    Settings adaptive;
    adaptive.plan = PLAN_ADAPTIVE;
    adaptive.atlas.cache = false;
    expectAllocationMatchesPlan(box, adaptive);
    Settings fixed = thesisAllocation();
    fixed.atlas.resolution = 256;
    fixed.atlas.cache = false;
    expectAllocationMatchesPlan(box, fixed);
}

TEST_F(ResourcePlanGpuTest, SponzaAllocatesItsPlan) {
    VOXATLAS_SPONZA_OR_SKIP(path);
    const scene::Scene sponza = loadTestScene(path);
    Settings adaptive;
    adaptive.plan = PLAN_ADAPTIVE;
    expectAllocationMatchesPlan(sponza, adaptive);
}

} // namespace
} // namespace gi::test
