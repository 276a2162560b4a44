#include "render/LineSpaceShadows.h"

#include "gl/Shared.h"
#include "render/ShadowCasters.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <cstdio>

namespace gi::render {
namespace {

// Groups for `count` invocations (or groups, with perGroup 1), spread over y past 65535.
void dispatchFlat(std::uint64_t count, std::uint64_t perGroup) {
    const std::uint64_t groups = std::max<std::uint64_t>((count + perGroup - 1) / perGroup, 1);
    const std::uint64_t x = std::min<std::uint64_t>(groups, 65535);
    glDispatchCompute(GLuint(x), GLuint((groups + x - 1) / x), 1);
}

bool bit(const std::vector<std::uint32_t>& words, std::uint64_t offset, std::uint64_t i) {
    return ((words[std::size_t(offset + i / 32)] >> (i % 32)) & 1u) != 0;
}

} // namespace

bool LineSpaceShadows::buildPrograms(gl::ShaderLibrary& shaders, std::string& error) {
    mVoxelize = shaders.build({"render/linespace_voxelize",
            {{GL_COMPUTE_SHADER, "render/linespace_voxelize.comp"}}, {}}, error);
    if (!mVoxelize) return false;
    mReduce = shaders.build({"render/linespace_reduce",
            {{GL_COMPUTE_SHADER, "render/linespace_reduce.comp"}}, {}}, error);
    if (!mReduce) return false;
    mShafts = shaders.build({"render/linespace_shafts",
            {{GL_COMPUTE_SHADER, "render/linespace_shafts.comp"}}, {}}, error);
    return bool(mShafts);
}

bool LineSpaceShadows::update(gl::ShaderLibrary& shaders, const scene::Scene& scene,
        std::uint64_t geometryVersion, const LineSpaceSettings& settings,
        gl::GpuProfiler& profiler, std::string& error) {
    if (mBuilt && geometryVersion == mGeometryVersion && mStats.n == settings.n &&
            mStats.depth == settings.depth) {
        return true;
    }
    const gl::GpuScope scope(profiler, "render/linespace/build");
    mBuilt = true;
    mGeometryVersion = geometryVersion;
    mStats.n = settings.n;
    mStats.depth = settings.depth;
    if (!mShafts && !buildPrograms(shaders, error)) return false;
    if (build(scene, settings.n, settings.depth, error)) return true;
    mNodes = {};
    mBits = {};
    return false;
}

void LineSpaceShadows::allocateNodes(const LineSpaceLayout& layout,
        const std::vector<std::uint32_t>& occupancy, std::vector<std::uint32_t>& children,
        std::vector<glm::uvec4>& cells) const {
    const std::uint64_t n = std::uint64_t(layout.n);
    const std::uint64_t perNode = n * n * n;
    cells.clear();
    if (!bit(occupancy, 0, 0)) return;
    cells.push_back(glm::uvec4(0u));
    // Breadth first: the children of node `i` are numbered when node i is reached.
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int level = int(cells[i].x);
        if (level + 1 >= layout.depth) break;
        const std::uint64_t r = layout.resolution(level + 1);
        const std::uint64_t offset = layout.occupancyOffset(level + 1);
        children.resize(std::max<std::size_t>(children.size(), (i + 1) * perNode), LINESPACE_EMPTY);
        for (std::uint64_t c = 0; c < perNode; ++c) {
            const glm::uvec3 child = glm::uvec3(cells[i].y, cells[i].z, cells[i].w) * unsigned(n) +
                                     glm::uvec3(unsigned(c % n), unsigned(c / n % n), unsigned(c / (n * n)));
            if (!bit(occupancy, offset, child.x + r * (child.y + r * child.z))) continue;
            children[i * perNode + c] = std::uint32_t(cells.size());
            cells.push_back(glm::uvec4(unsigned(level + 1), child));
        }
    }
}

bool LineSpaceShadows::build(const scene::Scene& scene, int n, int depth, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    const LineSpaceLayout layout = lineSpaceLayout(scene.bounds, n, depth);
    const std::vector<glm::vec4> corners = shadowCasterCorners(scene);
    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    if (double(layout.occupancyWords()) * 4.0 > double(maxBlock)) {
        error = "the leaf voxels of linespace.n " + std::to_string(n) + ", linespace.depth " +
                std::to_string(depth) + " exceed the driver's largest storage buffer";
        return false;
    }
    shader::GpuLineSpaceHeader header{};
    header.root = glm::vec4(layout.rootMin, layout.rootSize);
    header.shape = glm::ivec4(n, depth, int(layout.wordsPerNode()), 0);
    mNodes = gl::createBuffer(sizeof header, &header, 0, "render/linespace/nodes");
    gl::Buffer input = gl::createBuffer(std::max<std::size_t>(corners.size(), 3) * sizeof(glm::vec4),
            corners.empty() ? nullptr : corners.data(), 0, "render/linespace/build_triangles");
    gl::Buffer occupancy = gl::createBuffer(std::size_t(layout.occupancyWords()) * 4, nullptr, 0,
            "render/linespace/build_occupancy");
    glClearNamedBufferData(occupancy.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_NODES, mNodes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_OCCUPANCY, occupancy.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_INPUT, input.id());
    glUseProgram(mVoxelize.id());
    dispatchFlat(corners.size() / 3, 1);
    glUseProgram(mReduce.id());
    for (int level = depth - 1; level >= 0; --level) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        glProgramUniform1i(mReduce.id(), LOC_LINESPACE_LEVEL, level);
        dispatchFlat(layout.cells(level), LINESPACE_LOCAL_SIZE);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<std::uint32_t> inner(std::size_t(layout.occupancyOffset(depth)));
    glGetNamedBufferSubData(occupancy.id(), 0, GLsizeiptr(inner.size() * 4), inner.data());

    std::vector<std::uint32_t> children;
    std::vector<glm::uvec4> cells;
    allocateNodes(layout, inner, children, cells);
    header.shape.w = int(cells.size());
    std::vector<std::uint32_t> pool(sizeof header / 4 + children.size());
    std::memcpy(pool.data(), &header, sizeof header);
    std::copy(children.begin(), children.end(), pool.begin() + sizeof header / 4);
    mNodes = gl::createBuffer(pool.size() * 4, pool.data(), 0, "render/linespace/nodes");
    const std::size_t bitBytes = std::max<std::size_t>(cells.size(), 1) * layout.wordsPerNode() * 4;
    mBits = gl::createBuffer(bitBytes, nullptr, 0, "render/linespace/shafts");
    input = gl::createBuffer(std::max<std::size_t>(cells.size(), 1) * sizeof(glm::uvec4),
            cells.empty() ? nullptr : cells.data(), 0, "render/linespace/build_nodes");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_NODES, mNodes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_INPUT, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_BITS, mBits.id());
    glUseProgram(mShafts.id());
    dispatchFlat(cells.size() * ((layout.wordsPerNode() + LINESPACE_LOCAL_SIZE - 1) / LINESPACE_LOCAL_SIZE), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
    glFinish();

    mStats.n = n;
    mStats.depth = depth;
    mStats.triangles = corners.size() / 3;
    mStats.nodes = cells.size();
    mStats.bytes = pool.size() * 4 + cells.size() * layout.wordsPerNode() * 4;
    mStats.buildMilliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "linespace: LS(%d,%d) over %zu triangles: %zu nodes, %.2f MiB, built in %.0f ms\n",
            n, depth, mStats.triangles, mStats.nodes, double(mStats.bytes) / (1024.0 * 1024.0),
            mStats.buildMilliseconds);
    return true;
}

void LineSpaceShadows::bind() {
    if (!mNodes) {
        // No nodes: nothing is occluded.
        shader::GpuLineSpaceHeader header{};
        header.root = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        header.shape = glm::ivec4(4, 2, 1, 0);
        mNodes = gl::createBuffer(sizeof header, &header, 0, "render/linespace/nodes");
    }
    if (!mBits) mBits = gl::createBuffer(4, nullptr, 0, "render/linespace/shafts");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_NODES, mNodes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LINESPACE_BITS, mBits.id());
}

} // namespace gi::render
