// The sparse voxel octree of vpl.visibility=svo (gi/vpl/SparseVoxelOctree.h): its GPU build
// against what the occupancy implies (node count, the leaf set), its memory budget, and the
// restart march (shaders/common/svo_visibility.glsl) blocking a segment through a wall only.
#include "ComputeProbe.h"
#include "GpuTest.h"
#include "TestScenes.h"

#include "gi/vpl/SparseVoxelOctree.h"
#include "gl/Shared.h"
#include "scene/GpuScene.h"

#include <set>
#include <tuple>

namespace gi::test {
namespace {

using Leaf = std::tuple<unsigned, unsigned, unsigned>;

std::set<Leaf> leafSet(const std::vector<glm::uvec3>& leaves) {
    std::set<Leaf> set;
    for (const glm::uvec3& l : leaves) set.insert({l.x, l.y, l.z});
    return set;
}

// The nodes a top-down build must make for these leaves: the root, and 8 children for every
// node above the leaves that holds one.
std::size_t expectedNodes(const std::set<Leaf>& leaves, int depth) {
    std::size_t nodes = 1;
    for (int level = 0; level < depth; ++level) {
        const unsigned shift = unsigned(depth - level);
        std::set<Leaf> parents;
        for (const auto& [x, y, z] : leaves) parents.insert({x >> shift, y >> shift, z >> shift});
        nodes += 8 * parents.size();
    }
    return nodes;
}

// The occupied leaves reached from the root through the node words.
void collectLeaves(const std::vector<std::uint32_t>& nodes, std::uint32_t node, int level,
        int depth, glm::uvec3 corner, std::set<Leaf>& out) {
    ASSERT_LT(node, nodes.size());
    const std::uint32_t word = nodes[node];
    if ((word & SVO_NODE_FLAG) == 0u) return;
    if (level == depth) {
        out.insert({corner.x, corner.y, corner.z});
        return;
    }
    const std::uint32_t children = word & SVO_CHILD_MASK;
    ASSERT_NE(children, 0u) << "a flagged node above the leaves without children";
    for (unsigned slot = 0; slot < 8; ++slot) {
        const glm::uvec3 octant(slot & 1u, (slot >> 1) & 1u, (slot >> 2) & 1u);
        collectLeaves(nodes, children + slot, level + 1, depth, corner * 2u + octant, out);
    }
}

// A square of half-size h in the plane x = x0, centred on the x axis.
scene::Primitive wallAtX(float h, float x0) {
    scene::Primitive p;
    p.positions = {{x0, -h, -h}, {x0, h, -h}, {x0, h, h}, {x0, -h, h}};
    p.normals.assign(4, glm::vec3(1.0f, 0.0f, 0.0f));
    p.indices = {0, 1, 2, 0, 2, 3};
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    return p;
}

scene::Scene sceneOf(std::vector<scene::Primitive> primitives) {
    scene::Scene scene;
    scene.materials.resize(1);
    for (scene::Primitive& p : primitives) addPrimitive(scene, std::move(p));
    return scene;
}

class SvoGpuTest : public GpuTest {
protected:
    bool build(const scene::Scene& scene, const vpl::SvoCube& cube, int resolution,
            std::size_t budgetBytes, std::string& error) {
        mGpuScene = std::make_unique<scene::GpuScene>(scene);
        EXPECT_TRUE(mOctree.init(mShaders, error)) << error;
        gl::GpuProfiler profiler;
        const bool built = mOctree.build(*mGpuScene, cube, resolution, budgetBytes, profiler,
                error);
        profiler.flush();
        return built;
    }

    void expectConsistentTree(const std::set<Leaf>& fragments) {
        const int depth = mOctree.stats().depth;
        EXPECT_EQ(mOctree.stats().nodes, expectedNodes(fragments, depth));
        std::set<Leaf> reached;
        collectLeaves(mOctree.readNodes(), 0, 0, depth, glm::uvec3(0), reached);
        EXPECT_EQ(reached, fragments) << "the octree's leaves are the voxelized set";
    }

    gl::ShaderLibrary mShaders;
    std::unique_ptr<scene::GpuScene> mGpuScene;
    vpl::SparseVoxelOctree mOctree;
};

// A plate across the whole cube [0, 1]^3 at y = 0.53 fills layer 8 of a 16^3 octree: 256
// leaves, and at level l the 4^l nodes the layer passes through, each with 8 children:
// 1 + 8 (1 + 4 + 16 + 64) = 681 nodes.
TEST_F(SvoGpuTest, PlateBuildsOneLayerOfLeaves) {
    if (!mContext) GTEST_SKIP();
    std::string error;
    ASSERT_TRUE(build(sceneOf({horizontalSquare(2.0f, 0.53f)}), {glm::vec3(0.0f), 1.0f / 16.0f},
            16, 1 << 20, error)) << error;
    const std::set<Leaf> fragments = leafSet(mOctree.readFragmentLeaves());
    std::set<Leaf> layer;
    for (unsigned x = 0; x < 16; ++x) {
        for (unsigned z = 0; z < 16; ++z) layer.insert({x, 8u, z});
    }
    EXPECT_EQ(fragments, layer);
    EXPECT_EQ(mOctree.stats().leaves, 256u) << "each leaf once in the fragment list";
    EXPECT_EQ(mOctree.stats().nodes, 681u);
    EXPECT_EQ(mOctree.stats().bytes, 681u * 4u);
    expectConsistentTree(fragments);
}

TEST_F(SvoGpuTest, CornellBoxTreeHoldsExactlyTheVoxelizedLeaves) {
    if (!mContext) GTEST_SKIP();
    const scene::Scene cornell = loadCornellBox();
    std::string error;
    ASSERT_TRUE(build(cornell, vpl::SparseVoxelOctree::cubeAround(cornell.bounds, 64), 64,
            64 << 20, error)) << error;
    const std::set<Leaf> fragments = leafSet(mOctree.readFragmentLeaves());
    EXPECT_EQ(fragments.size(), mOctree.stats().leaves) << "no leaf twice in the list";
    EXPECT_GT(fragments.size(), 5u * 40u * 40u) << "five walls of about 60^2 leaves";
    expectConsistentTree(fragments);
}

TEST_F(SvoGpuTest, OctreeOverBudgetIsRefused) {
    if (!mContext) GTEST_SKIP();
    std::string error;
    EXPECT_FALSE(build(sceneOf({horizontalSquare(2.0f, 0.53f)}), {glm::vec3(0.0f), 1.0f / 16.0f},
            16, 600 * 4, error));
    EXPECT_NE(error.find("vpl.svo_budget_mb"), std::string::npos) << error;
    EXPECT_FALSE(mOctree.built() && mOctree.stats().nodes > 1);
}

struct SegmentCase {
    glm::vec4 receiver, receiverNormal, light, lightNormal;
};

SegmentCase segment(glm::vec3 receiver, glm::vec3 receiverNormal, glm::vec3 light,
        glm::vec3 lightNormal) {
    return {glm::vec4(receiver, 0.0f), glm::vec4(receiverNormal, 0.0f), glm::vec4(light, 0.0f),
            glm::vec4(lightNormal, 0.0f)};
}

// A wall in the plane x = 0.01 over y, z in [-0.5, 0.5], in a 64^3 octree over [-1, 1]^3.
TEST_F(SvoGpuTest, WallBlocksTheSegmentThroughItOnly) {
    if (!mContext) GTEST_SKIP();
    std::string error;
    ASSERT_TRUE(build(sceneOf({wallAtX(0.5f, 0.01f)}), {glm::vec3(-1.0f), 2.0f / 64.0f}, 64,
            1 << 20, error)) << error;
    mOctree.bind();
    const glm::vec3 px(1.0f, 0.0f, 0.0f), nx(-1.0f, 0.0f, 0.0f), py(0.0f, 1.0f, 0.0f);
    const std::vector<SegmentCase> cases = {
            segment({-0.5f, 0.0f, 0.0f}, px, {0.5f, 0.0f, 0.0f}, nx),          // through
            segment({-0.5f, 0.1f, 0.2f}, px, {0.6f, -0.3f, -0.1f}, nx),        // slanted, through
            segment({-0.5f, 0.8f, 0.0f}, px, {0.5f, 0.8f, 0.0f}, nx),          // over the top
            segment({-0.5f, 0.0f, 0.0f}, px, {-0.2f, 0.3f, 0.1f}, py),         // same side
            segment({0.01f, 0.1f, 0.1f}, nx, {-0.5f, 0.0f, 0.0f}, px),         // from the wall
            segment({0.01f, 0.1f, 0.1f}, px, {0.5f, 0.3f, 0.0f}, nx),          // from its back
    };
    const std::vector<glm::vec4> r =
            runComputeProbe<glm::vec4>("tests/gpu/shaders/svo_visibility_probe.comp", cases, error);
    ASSERT_EQ(r.size(), cases.size()) << error;
    EXPECT_EQ(r[0].x, 0.0f) << "a segment through the wall is blocked";
    EXPECT_EQ(r[1].x, 0.0f) << "a slanted segment through the wall is blocked";
    EXPECT_EQ(r[2].x, 1.0f) << "a segment over the wall passes";
    EXPECT_EQ(r[3].x, 1.0f) << "a segment on one side passes";
    EXPECT_EQ(r[4].x, 1.0f) << "the wall does not block light leaving its own front";
    EXPECT_EQ(r[5].x, 1.0f) << "nor its back";
}

} // namespace
} // namespace gi::test
