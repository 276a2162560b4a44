#include "gi/vpl/SparseVoxelOctree.h"

#include "gl/Shared.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace gi::vpl {
namespace {

constexpr GLuint groupsFor(std::size_t invocations) {
    return GLuint((invocations + SVO_LOCAL_SIZE - 1) / SVO_LOCAL_SIZE);
}

int log2Exact(int resolution) {
    int depth = 0;
    while ((1 << depth) < resolution) ++depth;
    return depth;
}

// At most every node of level l holds a leaf (min(leaves, 8^l)), and each flagged node above
// the leaves has 8 children.
std::size_t nodeBound(std::size_t leaves, int depth) {
    std::size_t nodes = 1, levelNodes = 1;
    for (int level = 0; level < depth; ++level) {
        nodes += 8 * std::min(leaves, levelNodes);
        levelNodes = std::min(levelNodes * 8, leaves);
    }
    return nodes;
}

} // namespace

SvoCube SparseVoxelOctree::cubeAround(const scene::Aabb& bounds, int resolution) {
    if (bounds.empty()) return {};
    const glm::vec3 size = bounds.max - bounds.min;
    const float extent = std::max({size.x, size.y, size.z, 1e-6f});
    const float leaf = extent / float(std::max(resolution - 2, 1));
    const glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
    return {centre - 0.5f * leaf * float(resolution), leaf};
}

bool SparseVoxelOctree::init(gl::ShaderLibrary& shaders, std::string& error) {
    mVoxelize = shaders.build({"vpl/svo_voxelize",
            {{GL_VERTEX_SHADER, "vpl/svo_voxelize.vert"},
                    {GL_GEOMETRY_SHADER, "vpl/svo_voxelize.geom"},
                    {GL_FRAGMENT_SHADER, "vpl/svo_voxelize.frag"}},
            {}}, error);
    auto pass = [&](const char* name, const char* define) {
        return shaders.build({name, {{GL_COMPUTE_SHADER, "vpl/svo_build.comp"}},
                {std::string("SVO_PASS ") + define}}, error);
    };
    if (!mVoxelize) return false;
    mFlag = pass("vpl/svo_flag", "SVO_PASS_FLAG");
    if (!mFlag) return false;
    mAllocate = pass("vpl/svo_allocate", "SVO_PASS_ALLOCATE");
    if (!mAllocate) return false;
    mAdvance = pass("vpl/svo_advance", "SVO_PASS_ADVANCE");
    if (!mAdvance) return false;
    mFramebuffer = gl::createFramebuffer("vpl/svo_voxelize");
    mUniforms = gl::createBuffer(sizeof(shader::SvoUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT,
            "vpl/svo_uniforms");
    mBuildState = gl::createBuffer(sizeof(shader::SvoBuildState), nullptr,
            GL_DYNAMIC_STORAGE_BIT, "vpl/svo_build_state");
    return true;
}

void SparseVoxelOctree::writeUniforms(const SvoCube& cube, int resolution, std::size_t capacity) {
    shader::SvoUniforms u{};
    u.cube = glm::vec4(cube.lowest, cube.leafSize);
    u.shape = glm::ivec4(resolution, log2Exact(resolution), resolution * kRasterPerLeaf,
            int(std::min<std::size_t>(capacity, SVO_CHILD_MASK)));
    u.march = glm::vec4(kEndPush, kEndShrink, kExitEpsilon, 0.0f);
    glNamedBufferSubData(mUniforms.id(), 0, sizeof u, &u);
}

std::size_t SparseVoxelOctree::runVoxelization(const scene::GpuScene& scene, int resolution) {
    const GLuint zero = 0;
    glClearNamedBufferData(mLeafBits.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glNamedBufferSubData(mFragments.id(), 0, sizeof zero, &zero);
    const int raster = resolution * kRasterPerLeaf;
    glNamedFramebufferParameteri(mFramebuffer.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, raster);
    glNamedFramebufferParameteri(mFramebuffer.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, raster);
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, raster, raster);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mVoxelize.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_SVO, mUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_MATERIALS, scene.materialBuffer().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_LEAF_BITS, mLeafBits.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_FRAGMENTS, mFragments.id());
    scene.drawAll(mVoxelize.id(), false);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    GLuint count = 0;
    glGetNamedBufferSubData(mFragments.id(), 0, sizeof count, &count);
    return count;
}

std::size_t SparseVoxelOctree::voxelize(const scene::GpuScene& scene, int resolution,
        gl::GpuProfiler& profiler) {
    gl::GpuScope scope(profiler, "vpl/svo_voxelize");
    const std::size_t leafBits = std::size_t(resolution) * resolution * resolution;
    const std::size_t bitBytes = (leafBits + 31) / 32 * sizeof(GLuint);
    if (!mLeafBits || mStats.resolution != resolution) {
        mLeafBits = gl::createBuffer(bitBytes, nullptr, 0, "vpl/svo_leaf_bits");
    }
    // A first guess of six faces of the cube's surface; grown to fit when it overflows.
    std::size_t needed = std::max(mFragmentCapacity, std::size_t(6) * resolution * resolution);
    for (;;) {
        if (needed > mFragmentCapacity) {
            mFragmentCapacity = needed;
            mFragments = gl::createBuffer((mFragmentCapacity + 1) * sizeof(GLuint), nullptr,
                    GL_DYNAMIC_STORAGE_BIT, "vpl/svo_fragments");
        }
        const std::size_t count = runVoxelization(scene, resolution);
        if (count <= mFragmentCapacity) return count;
        needed = count;
    }
}

bool SparseVoxelOctree::buildLevels(std::size_t leaves, std::size_t capacity, int depth,
        gl::GpuProfiler& profiler, std::size_t& nodes) {
    gl::GpuScope scope(profiler, "vpl/svo_build");
    mPool = gl::createBuffer(capacity * kBytesPerNode, nullptr, 0, "vpl/svo_pool");
    const GLuint root = 0;
    glClearNamedBufferSubData(mPool.id(), GL_R32UI, 0, kBytesPerNode, GL_RED_INTEGER,
            GL_UNSIGNED_INT, &root);
    shader::SvoBuildState state{};
    state.dispatch = glm::ivec4(1, 1, 1, 0);
    state.counts = glm::ivec4(1, 0, 0, 0);
    state.levelStart[1] = 1;
    glNamedBufferSubData(mBuildState.id(), 0, sizeof state, &state);

    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_SVO, mUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_NODES, mPool.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_FRAGMENTS, mFragments.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_BUILD, mBuildState.id());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, mBuildState.id());
    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;
    for (int level = 0; level <= depth; ++level) {
        glUseProgram(mFlag.id());
        glProgramUniform1i(mFlag.id(), LOC_SVO_LEVEL, level);
        glDispatchCompute(groupsFor(leaves), 1, 1);
        glMemoryBarrier(barrier);
        if (level == depth) break;
        glUseProgram(mAllocate.id());
        glProgramUniform1i(mAllocate.id(), LOC_SVO_LEVEL, level);
        glDispatchComputeIndirect(0);
        glMemoryBarrier(barrier);
        glUseProgram(mAdvance.id());
        glProgramUniform1i(mAdvance.id(), LOC_SVO_LEVEL, level);
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(barrier);
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glUseProgram(0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(mBuildState.id(), 0, sizeof state, &state);
    nodes = std::size_t(state.counts.x);
    return state.counts.y == 0 && nodes <= capacity;
}

bool SparseVoxelOctree::build(const scene::GpuScene& scene, const SvoCube& cube, int resolution,
        std::size_t budgetBytes, gl::GpuProfiler& profiler, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    const int depth = log2Exact(resolution);
    const std::size_t budgetNodes = budgetBytes / kBytesPerNode;
    writeUniforms(cube, resolution, budgetNodes);
    const std::size_t leaves = voxelize(scene, resolution, profiler);
    mStats = {resolution, depth, leaves, 0, 0, 0.0};
    const std::size_t capacity = std::min(budgetNodes, nodeBound(leaves, depth));
    writeUniforms(cube, resolution, capacity);
    std::size_t nodes = 0;
    const bool fits = capacity > 0 && buildLevels(leaves, capacity, depth, profiler, nodes);
    if (fits) {
        mNodes = gl::createBuffer(nodes * kBytesPerNode, nullptr, 0, "vpl/svo_nodes");
        glCopyNamedBufferSubData(mPool.id(), mNodes.id(), 0, 0, GLsizeiptr(nodes * kBytesPerNode));
        mStats.nodes = nodes;
        mStats.bytes = nodes * kBytesPerNode;
    } else {
        // An empty root: nothing occludes.
        const GLuint empty = 0;
        mNodes = gl::createBuffer(kBytesPerNode, &empty, 0, "vpl/svo_nodes");
        char line[256];
        std::snprintf(line, sizeof line,
                "vpl.svo_budget_mb: the sparse voxel octree at %d^3 (%zu occupied leaves) needs "
                "over %zu nodes, more than the %.0f MiB budget; raise vpl.svo_budget_mb or lower "
                "vpl.svo_resolution",
                resolution, leaves, nodes, double(budgetBytes) / double(1 << 20));
        error = line;
    }
    mPool = {};
    mStats.buildMilliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
    return fits;
}

void SparseVoxelOctree::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_SVO, mUniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_SVO_NODES, mNodes.id());
}

std::vector<std::uint32_t> SparseVoxelOctree::readNodes() const {
    std::vector<std::uint32_t> nodes(mStats.nodes);
    glGetNamedBufferSubData(mNodes.id(), 0, GLsizeiptr(nodes.size() * kBytesPerNode),
            nodes.data());
    return nodes;
}

std::vector<glm::uvec3> SparseVoxelOctree::readFragmentLeaves() const {
    std::vector<std::uint32_t> packed(mStats.leaves);
    glGetNamedBufferSubData(mFragments.id(), sizeof(GLuint),
            GLsizeiptr(packed.size() * sizeof(GLuint)), packed.data());
    const std::uint32_t mask = (1u << SVO_COORD_BITS) - 1u;
    std::vector<glm::uvec3> leaves;
    leaves.reserve(packed.size());
    for (const std::uint32_t p : packed) {
        leaves.emplace_back(p & mask, (p >> SVO_COORD_BITS) & mask,
                (p >> (2 * SVO_COORD_BITS)) & mask);
    }
    return leaves;
}

} // namespace gi::vpl
