#include "gi/vpl/VplGatherPass.h"

#include "gi/vpl/PixelDispatch.h"
#include "gl/LoopBudget.h"
#include "gl/RenderTarget.h"
#include "gl/Shared.h"

namespace gi::vpl {

bool VplGatherPass::init(gl::ShaderLibrary& shaders, std::string& error) {
    // One shader, compiled once per way of testing visibility.
    auto gather = [&](const char* name, const char* visibility) {
        return shaders.build({name, {{GL_COMPUTE_SHADER, "vpl/gather.comp"}},
                                     {std::string("VPL_VISIBILITY ") + visibility}},
                error);
    };
    mUnoccluded = gather("vpl/gather_none", "VPL_VISIBILITY_NONE");
    if (!mUnoccluded) return false;
    mCascade = gather("vpl/gather_cascade", "VPL_VISIBILITY_CASCADE");
    if (!mCascade) return false;
    mOctree = gather("vpl/gather_svo", "VPL_VISIBILITY_SVO");
    if (!mOctree) return false;
    mRays = gather("vpl/gather_bvh", "VPL_VISIBILITY_BVH");
    return bool(mRays);
}

void VplGatherPass::execute(const Inputs& in, gl::GpuProfiler& profiler) {
    const glm::ivec2 size = in.gBuffer.size();
    if (size != mSize) {
        mSize = size;
        mResult = gl::createTargetTexture({GL_RGBA32F, "vpl/gathered"}, size);
    }
    // The gather's own cost, apart from the filter: with cascade visibility most of it is the
    // march (results-vpl.md compares it with vpl.visibility=none).
    const bool rays = in.bvhRayIterations > 0 && !in.occupancy && !in.octree;
    gl::GpuScope scope(profiler, in.occupancy ? "vpl/gather_cascade"
                                 : in.octree  ? "vpl/gather_svo"
                                 : rays       ? "vpl/gather_bvh"
                                              : "vpl/gather");
    const GLuint program = in.occupancy ? mCascade.id()
                           : in.octree  ? mOctree.id()
                           : rays       ? mRays.id()
                                        : mUnoccluded.id();
    glUseProgram(program);
    glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VPL, in.uniforms.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_VPLS, in.vpls.id());
    glBindTextureUnit(BIND_TEX_VPL_POSITION, in.gBuffer.position().id());
    glBindTextureUnit(BIND_TEX_VPL_NORMAL, in.gBuffer.normal().id());
    if (in.occupancy) {
        in.occupancy->bind();
    }
    if (in.octree) in.octree->bind();
    const int segment = in.occupancy ? in.occupancy->visibilityLoopIterations()
                        : in.octree  ? in.octree->visibilityLoopIterations()
                        : rays       ? in.bvhRayIterations
                                     : 0;
    const std::vector<glm::ivec2> ranges =
            gl::rangesWithinLoopBudget(std::max(in.vplsPerPixel, 1), 1 + segment);
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        // Each dispatch reads what the one before stored.
        if (i > 0) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glUseProgram(program);   // dispatchOverPixels ends with none
        glProgramUniform3i(program, LOC_VPL_GATHER_RANGE, ranges[i].x, ranges[i].y,
                i + 1 == ranges.size() ? 1 : 0);
        dispatchOverPixels(mResult, size, i > 0 ? GL_READ_WRITE : GL_WRITE_ONLY, GL_RGBA32F);
    }
}

} // namespace gi::vpl
