#include "render/BvhShadows.h"

#include "gl/Shared.h"
#include "render/ShadowCasters.h"

namespace gi::render {

bool BvhShadows::update(const scene::Scene& scene, std::uint64_t geometryVersion,
        gl::GpuProfiler& profiler, std::string& error) {
    if (mBuilt && geometryVersion == mGeometryVersion) return true;
    const gl::GpuScope scope(profiler, "render/bvh/build");
    reference::GpuBvh bvh;
    const bool ok = reference::buildGpuBvh(shadowCasterCorners(scene), bvh, error);
    if (!ok) return false;
    mBvh = std::move(bvh);
    mNodes = gl::createBuffer(mBvh.nodes.size() * sizeof(glm::vec4), mBvh.nodes.data(), 0, "render/bvh/nodes");
    mTriangles = gl::createBuffer(std::max<std::size_t>(mBvh.triangles.size(), 1) * sizeof(glm::vec4),
            mBvh.triangles.empty() ? nullptr : mBvh.triangles.data(), 0, "render/bvh/triangles");
    mBuilt = true;
    mGeometryVersion = geometryVersion;
    return true;
}

void BvhShadows::bind() {
    if (!mNodes) {
        // An empty tree (one leaf that nothing meets) until the method is used.
        const glm::vec4 empty[2] = {glm::vec4(1.0f, 1.0f, 1.0f, 0.0f), glm::vec4(-1.0f, -1.0f, -1.0f, 0.0f)};
        mNodes = gl::createBuffer(sizeof empty, empty, 0, "render/bvh/nodes");
        mTriangles = gl::createBuffer(sizeof(glm::vec4), nullptr, 0, "render/bvh/triangles");
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_BVH_NODES, mNodes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_BVH_TRIANGLES, mTriangles.id());
}

} // namespace gi::render
