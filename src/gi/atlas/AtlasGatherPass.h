// Atlas gather (thesis 4.6): one fragment per atlas texel reads N sample texels (the area
// estimator's from AtlasSenderSamplingPass, the thesis' at the Hammersley points) and adds the
// senders' direct light (estimator and visibility in shaders/atlas/gather.frag). The result is
// added to running sums by blending, so successive rotated sample sets accumulate (progressive
// mode); clear() starts over.
// Inputs : AtlasTextures direct, normal, position; the Hammersley texture (RG32F, N x 1);
//          the sender sampling table and point pool; AtlasUniforms (R, N, estimator,
//          rotation offset, estimator constant); optionally a voxel occupancy volume or the
//          scene's BVH for visibility.
// Outputs: AtlasTextures sums (RGBA32F): rgb += estimator constant x sum over this set,
//          a = 1 where a receiver was written.
// A set is drawn in several draws, the sky's directions, the near field's and then ranges of
// the samples, each within SHADER_LOOP_ITERATIONS for the visibility walk's longest segments
// (gl/LoopBudget.h).
// With gi.bounces > 1 bounce b reads the senders of AtlasTextures::senderRadiance(b) and adds
// to sumsOf(b).
#pragma once

#include "gi/GiTechnique.h"
#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasSenderSamplingPass.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"

#include <vector>

namespace gi::atlas {

class AtlasGatherPass {
public:
    struct Inputs {
        const AtlasTextures& textures;    // direct, normal, position of the G-buffer
        const gl::Texture& samples;       // RG32F, N x 1 Hammersley points in [0,1)^2
        const gl::Buffer& atlasUniforms;  // AtlasUniforms, std140: R, N, estimator, rotation
        const OccupancyVolume* occupancy; // nullptr: no visibility test
        const AtlasSenderSamplingPass& senderSampling; // executed for this set (area estimator)
        int bounce = 0;                   // 0: the direct light's gather, b: bounce b's
        int sampleCount = 0;              // N, the set's samples (AtlasUniforms size.y)
        int skyDirections = 0;            // the sky's directions per set (AtlasUniforms sky.w)
        // > 0: visibility by rays through the scene's BVH bound at BIND_SSBO_BVH_* (instead of
        // the occupancy), each running at most this many loop iterations.
        int bvhRayIterations = 0;
        // The near field (shaders/atlas/near_field.glsl): its rays per receiver side and set
        // (AtlasUniforms nearField.x), through the BVH bound at BIND_SSBO_BVH_* when `bvhNodes`
        // (its node count) > 0, finding their texels through `geometry`'s triangles.
        int nearRays = 0;
        int bvhNodes = 0;
        const AtlasGeometry* geometry = nullptr;
    };

    // Nodes a near-field ray's walk visits at most: its segment is atlas.near_reach texel
    // edges long, so it meets few of any tree's; a walk cut short counts as meeting nothing.
    static constexpr int kNearRayNodes = 512;
    struct Outputs {
        const AtlasTextures& textures;    // sumsOf(bounce), a layer attach() bound (blended into)
    };

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Draws into textures.sumsOf(b) from now on; false with a message if that is not renderable.
    bool attach(const AtlasTextures& textures, std::string& error);
    // Zeroes the sums of every bounce: the next execute starts a new accumulation.
    void clear();
    void execute(const Inputs& in, const Outputs& out, gl::GpuProfiler& profiler);

private:
    gl::ProgramRef mProgram, mVoxelProgram, mBvhProgram;
    std::vector<gl::Framebuffer> mFramebuffers;   // one per bounce
    gl::VertexArray mEmpty;
    int mResolution = 0;
};

} // namespace gi::atlas
