// Senders of the area estimator (shaders/atlas/sender_sampling.comp), drawn in proportion to
// the power each atlas texel sends: p(y) = a(y) mean(L(y)) / P, with a(y) the surface area the
// texel stands for (position.w), L(y) its direct radiance and P the sum over all texels. The
// gather's estimate P/N sum L(y)/mean(L(y)) cos cos / r^2 is the area form of E_ind (SEEDS.md
// section 2) importance-sampled: no sample is spent on gutters, empty texels or unlit surfaces,
// and bright spots (a lamp close to a wall) are sampled as often as the light they send.
// Uniform points over the atlas spend most samples where nothing is sent (Sponza: 55-80% of
// the atlas is empty and most of its surface is unlit) and rarely meet small bright spots.
//  - table (after each G-buffer): per atlas row, prefix sums of a(y) mean(L(y)) at the end of
//    every ATLAS_SENDER_BLOCK texels, and prefix sums over rows (the last one is P).
//  - pool (every sample set): N strata of equal power in row-major order, ATLAS_POOL_STRIDE
//    evenly spaced points in each (shifted by the set's rotation), each turned into the texel
//    holding it by inverting the prefix sums. A receiver takes one point per stratum, picked by
//    a hash of the receiver and the stratum: every receiver's set is stratified, and
//    neighbouring receivers see different senders, so an unlucky set of points becomes noise
//    between texels instead of one error shared by the whole image.
// With atlas.importance (by default =surfaces) each texel's power is also weighed by how much of
// its light a set of receivers can receive (sender_weight.glsl, the analogue of the VPLs' draw, results-vpl.md):
// the senders those receivers can see are drawn more often and carry less each, so the
// estimate stays unbiased and the noise falls where most of the power goes elsewhere (a sunlit
// ground outside a room, whose light leaves for the sky).
//  - receivers, either the surfaces the camera sees (atlas.importance=view: takeViewSamples,
//    at the centres of ATLAS_VIEW_SAMPLES_PER_SIDE^2 cells of the image, from a resolve's view
//    depth) or the scene's own surfaces (atlas.importance=surfaces: takeSurfaceSamples,
//    ATLAS_SURFACE_POINTS points on the scene's triangles spread by area, SurfacePoints.h,
//    placed from the posed vertices; no view, so the lit atlas stays the same from every
//    view, noise included).
//  - importance (computeImportance): per texel and side, the gather's kernel without
//    visibility summed over the receivers, into an RG32F layer of the atlas' size.
// Inputs : AtlasTextures direct (rgb = L, a > 0: written) and position (w = a(y), m^2);
//          AtlasUniforms (R, N, sampling.x = the set's rotation, importance: the floor's share,
//          the receivers' cells and the kernel's smallest r^2).
// Outputs: the buffers at BIND_SSBO_ATLAS_SENDER_ROWS / _BLOCKS / _POOL (shared.h), owned by
//          the pass (sized by R and N) and bound by bind() for the gather, with the importance
//          layer at BIND_TEX_ATLAS_IMPORTANCE.
#pragma once

#include "core/Settings.h"
#include "gi/atlas/AtlasTextures.h"
#include "gi/atlas/SurfacePoints.h"
#include "gl/GpuProfiler.h"
#include "gl/MemoryRegistry.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

#include <vector>

namespace gi::atlas {

class AtlasSenderSamplingPass {
public:
    struct Inputs {
        const AtlasTextures& textures;     // direct (rgb = L, W/(m^2 sr)), position (w = m^2)
        const gl::Buffer& atlasUniforms;   // AtlasUniforms, std140: R, N, set rotation
        int samples;                       // N, points in the pool
        bool rebuildTable;                 // the senders' radiance changed since the last execute
        int bounce = 0;                    // whose senders: textures.senderRadiance(bounce)
    };

    // Whether `settings` draw the senders by an importance (atlas.importance other than power,
    // with the area estimator, the only one that draws senders).
    [[nodiscard]] static bool drawsByImportance(const AtlasSettings& settings);
    // The importance's memory for an atlas of `resolution` texels a side when `settings` draw
    // by importance (its layer, the receivers and the surface points), none otherwise.
    [[nodiscard]] static std::vector<gl::MemoryItem> importanceMemoryFor(
            const AtlasSettings& settings, int resolution);

    bool init(gl::ShaderLibrary& shaders, std::string& error);
    // Rebuilds the power table from the G-buffer when asked to (or when the atlas resolution
    // changed), then the point pool of the current set.
    void execute(const Inputs& in, gl::GpuProfiler& profiler);
    // Binds the table, the pool and the importance layer for a consumer (the gather).
    void bind() const;

    // Allocates the importance layer for an atlas of `resolution` texels a side, or with 0
    // releases it for a 1 x 1 layer of zeros (senders drawn by power alone).
    void reserveImportance(int resolution);
    // The receivers computeImportance weighs texels by: the surfaces the camera sees, from the
    // view depth in `viewIndirect`'s alpha (the resolve's output, drawn with `frameUniforms`).
    void takeViewSamples(const gl::Texture& viewIndirect, const gl::Buffer& frameUniforms,
            gl::GpuProfiler& profiler);
    // Or the scene's own surfaces: the points last set, placed from `sceneVertices`
    // (GpuScene's posed vertices; `atlasUniforms`: the points' count and area).
    void setSurfacePoints(const SurfacePoints& points);
    void takeSurfaceSamples(const gl::Buffer& sceneVertices, const gl::Buffer& atlasUniforms,
            gl::GpuProfiler& profiler);
    // The importance of each texel that sends light, for the last receivers taken (the
    // power is weighed in when the table is built). Again whenever the direct light changes
    // which texels send; the table must be rebuilt after it.
    void computeImportance(const AtlasTextures& textures, const gl::Buffer& atlasUniforms,
            gl::GpuProfiler& profiler);
    // The receivers last taken, two per cell (position with w = its weight, 0 where no surface
    // is; normal with w = 1 where both sides receive), read back (waits for the GPU): for tests.
    [[nodiscard]] std::vector<glm::vec4> readReceivers() const;
    // Cells of the receivers last taken (0 before any).
    [[nodiscard]] int receiverCells() const { return mReceiverCells; }

private:
    // Runs `program`, one of the receiver steps, over `cells` cells into mReceivers.
    void writeReceivers(const gl::ProgramRef& program, std::size_t cells);

    gl::ProgramRef mRows, mPrefix, mPool, mViewSamples, mSurfaceSamples, mImportance;
    gl::Buffer mRowPower, mBlockPower, mPoints, mReceivers, mSurfacePoints;
    gl::Texture mImportanceLayer;   // RG32F, R x R once computed; 1 x 1 zero before
    int mResolution = 0, mSamples = 0, mImportanceResolution = 0, mReceiverCells = 0;
    int mSurfacePointCount = 0;
};

} // namespace gi::atlas
