// Many-lights GI with virtual point lights (SEEDS.md section 4; Keller 1997, Dachsbacher and
// Stamminger 2005, and the seed's interleaved sampling with voxel visibility). When lights or
// geometry change:
//   1. reflective shadow maps of every light (ReflectiveShadowMapPass through scene/LightViews.h),
//   2. vpl.count VPLs drawn from their lit texels in proportion to flux (VplSampler);
//      with vpl.bounces=2, a share of the count (kSecondGenerationShare) are instead rays from
//      these VPLs through the voxel occupancy, each hit a VPL of the flux reflected there
//      (VplBouncePass); the gather treats both generations alike;
// every frame:
//   3. the camera's G-buffer (VplGBufferPass); with vpl.importance (the default) the VPLs are
//      drawn in proportion to flux x the light the view's surfaces can receive from each texel
//      (VplImportance), again when the camera has moved or turned far enough,
//   4. the gather (VplGatherPass): E_ind = sum phi/pi V cos cos / max(B, r^2), each pixel of a
//      4x4 tile using one sixteenth of the VPLs, V through the voxel occupancy
//      (vpl.visibility=cascade), the sparse voxel octree (svo, SvoVisibility) or 1,
//   5. the geometry-aware merge of the tiles (VplFilterPass) -> screen-space E_ind.
// vpl.clamp = 0 takes B = kClampPerVplArea x the surface area one VPL stands for: the 1/r^2
// spike is cut where one VPL no longer stands for the light around it, which scales with the
// scene and with the VPL count (a fraction of the scene's diagonal clamped a 40 m atrium over
// 1.2 m and lost a fifth of its indirect light). That area is the mean's (the area the most
// widely lit light reaches, over the first generation's count; clampArea()), or a VPL's own
// (its texel's area over the copies drawn of it) where that is larger: the VPLs the view's
// importance draws sparsely carry the light of more surface. Cutting the densely drawn ones
// closer than the mean's B spiked next to sunlit corners (Sponza's sun 0.495 -> 0.837);
// results-vpl.md measures what the clamp costs in energy.
#pragma once

#include "gi/GiTechnique.h"
#include "gi/vpl/VplDebugPass.h"
#include "gi/vpl/ReflectiveShadowMapPass.h"
#include "gi/vpl/VplBouncePass.h"
#include "gi/vpl/VplFilterPass.h"
#include "gi/vpl/VplGBufferPass.h"
#include "gi/vpl/SvoVisibility.h"
#include "gi/vpl/VplGatherPass.h"
#include "gi/vpl/VplReport.h"

namespace gi::vpl {

class VplGi final : public GiTechnique {
public:
    // B over the lit area per VPL when vpl.clamp = 0.
    static constexpr float kClampPerVplArea = 0.25f;
    // The share of vpl.count that vpl.bounces=2 spends on second-generation rays
    // (results-vpl.md measures the split).
    static constexpr float kSecondGenerationShare = 0.5f;

    const char* name() const override { return "vpl"; }
    bool init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) override;
    bool configure(const Settings& settings, std::string& error) override;
    void update(const GiFrameInputs& in, gl::GpuProfiler& profiler) override;
    GiOutputs outputs() const override;
    std::string status() const override;
    std::string failure() const override { return mSvo.failure(); }

    // VPLs drawn at the last resampling (fewer than vpl.count only when nothing is lit).
    int vplCount() const { return mVplCount; }
    // B (m^2) of the gather's 1 / max(B, r^2).
    float clampArea() const;
    // The last resampling and this frame's gather, for --timings, the overlay and tests.
    [[nodiscard]] VplReport report() const;

private:
    // What the VPLs were drawn from: another state draws them anew.
    struct Source {
        const scene::GpuScene* scene = nullptr;
        std::vector<scene::Light> lights;
        std::uint64_t geometryVersion = 0;
        std::uint64_t occupancyVersion = 0;   // what the second generation was traced through
        bool valid = false;
    };

    // Renders the lights' RSMs and reads their lit texels back (when lights or geometry change).
    void renderReflectiveShadowMaps(const GiFrameInputs& in, gl::GpuProfiler& profiler);
    // Draws the VPLs from the texels: by flux, or by flux x the view's importance
    // (vpl.importance), which a moved camera redraws; `announce` prints what was drawn.
    void drawFromTexels(const GiFrameInputs& in, gl::GpuProfiler& profiler, bool announce);
    // vpl.count split between the generations: {first-generation VPLs, bounce rays}.
    glm::ivec2 generationCounts() const;
    void addSecondGeneration(std::vector<shader::GpuVpl>& vpls, const GiFrameInputs& in,
            gl::GpuProfiler& profiler);
    const OccupancyVolume* visibilityOccupancy(const GiFrameInputs& in);
    // The loop iterations of a ray through the scene's BVH (vpl.visibility=bvh), or 0.
    int visibilityBvh(const GiFrameInputs& in);
    void writeUniforms(int visibility, int gatherOutput);

    VplSettings mSettings;
    bool mGlossyMaterials = false;   // material.model=gltf: the RSM's flux is the glTF BRDF's
    float mLitAreaPerVpl = 0.0f;   // m^2, at the last resampling
    Source mSource;
    int mVplCount = 0;
    int mSecondGenerationCount = 0;
    bool mWarnedNoVisibility = false;   // a missing occupancy or BVH is reported once
    bool mHasOutput = false;
    int mVisibility = VPL_VISIBILITY_NONE;   // VPL_VISIBILITY_* of this frame's gather
    float mRayOffset = 0.0f;                 // VplUniforms rays.x
    int mDebugView = -1;   // VPL_DEBUG_* shown this frame, -1 = none
    VplReport mLastResampling;   // its RSM and sampling fields
    std::vector<RsmTexel> mTexels;   // the lit RSM texels the VPLs are drawn from
    scene::CameraView mDrawnFor;     // the camera the VPLs were last drawn for

    gl::Buffer mVpls;
    gl::Buffer mUniforms;
    ReflectiveShadowMapPass mRsm;
    VplGBufferPass mGBuffer;
    VplBouncePass mBounce;
    VplGatherPass mGather;
    VplFilterPass mFilter;
    SvoVisibility mSvo;
    VplDebugPass mDebug;
};

} // namespace gi::vpl
