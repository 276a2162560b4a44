// Texture-atlas GI (SEEDS.md section 2; Merz 2010, "Atlas-basierte globale Beleuchtung im
// Bildraum"): the indirect light is gathered on an atlas that holds every surface of the
// scene, so it does not depend on what the camera sees (thesis 3.1). Per frame:
//   1. atlas G-buffer: direct radiance, normal, position + sample area, albedo (4.4),
//   2. gather: N samples per texel (4.5, 4.6), area-form or thesis weighting, optional voxel
//      visibility, added to running sums (the area form draws its senders in proportion to
//      the power they send, AtlasSenderSamplingPass; the thesis' weighting reads Hammersley
//      points),
//   3. normalise and dilate into the gutters -> lit atlas of E_ind (W/m^2),
//   4. resolve: the lit atlas seen from the camera -> screen-space E_ind (4.7).
// Progressive mode (the thesis' future work, 5.4): a static scene's G-buffer is built once and
// each frame adds one more rotated sample set until atlas.target_samples; changes to lights,
// geometry or settings start over. The atlas parameterisation (AtlasBuilder) is built when
// the resolution or gutter changes, through the disk cache (AtlasCache). Animated instances
// keep their charts; their atlas vertices follow the pose (AtlasPosePass) and the G-buffer and
// sums start over whenever the geometry moves.
#pragma once

#include "gi/GiTechnique.h"
#include "gi/atlas/AtlasCache.h"
#include "gi/atlas/AtlasDebugViewPass.h"
#include "gi/atlas/AtlasDilatePass.h"
#include "gi/atlas/AtlasGBufferPass.h"
#include "gi/atlas/AtlasGatherPass.h"
#include "gi/atlas/AtlasGeometry.h"
#include "gi/atlas/AtlasPosePass.h"
#include "gi/atlas/AtlasResolvePass.h"
#include "gi/atlas/AtlasSenderSamplingPass.h"
#include "gi/atlas/AtlasTextures.h"
#include "gl/Shared.h"

namespace gi::atlas {

class AtlasGi final : public GiTechnique {
public:
    const char* name() const override { return "atlas"; }
    bool init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) override;
    bool configure(const Settings& settings, std::string& error) override;
    void update(const GiFrameInputs& in, gl::GpuProfiler& profiler) override;
    GiOutputs outputs() const override;

    // Samples per texel accumulated into the lit atlas so far (progressive mode's progress).
    int accumulatedSamples() const { return mSamplesDone; }
    std::string status() const override;
    // For tests and the overlay.
    const Atlas& atlas() const { return mAtlas; }
    const AtlasBuildInfo& buildInfo() const { return mBuildInfo; }
    const AtlasTextures& textures() const { return mTextures; }

private:
    bool buildAtlasGeometry(std::string& error);
    void writeUniforms();
    bool inputsChanged(const GiFrameInputs& in);

    AtlasMesh mMesh;
    Atlas mAtlas;
    AtlasBuildInfo mBuildInfo;
    AtlasSettings mSettings;
    ShadowSettings mShadowSettings;
    bool mConfigured = false;

    AtlasGeometry mGeometry;
    AtlasTextures mTextures;
    gl::Texture mSamples;
    gl::Buffer mUniforms;
    shader::AtlasUniforms mUniformData{};

    // What the current G-buffer and sums were computed for.
    bool mGBufferValid = false;
    bool mSenderTableValid = false; // the sender sampling table matches the G-buffer
    int mSamplesDone = 0;
    std::uint32_t mSetIndex = 0;   // rotated sets accumulated since the last restart
    std::uint32_t mFrameIndex = 0; // frames since configure (non-progressive rotation)
    std::vector<scene::Light> mLights;
    const scene::GpuScene* mScene = nullptr;
    std::uint64_t mGeometryVersion = 0;
    std::uint64_t mOccupancyVersion = 0;
    bool mHadOccupancy = false;
    bool mWarnedNoOccupancy = false;
    bool mShowDebug = false;

    // Animated instances: the atlas vertices follow GpuScene's pose (AtlasPosePass).
    bool mFollowsPose = false;
    std::uint64_t mPosedGeometry = ~std::uint64_t(0);

    AtlasPosePass mPose;
    AtlasGBufferPass mGBuffer;
    AtlasSenderSamplingPass mSenderSampling;
    AtlasGatherPass mGather;
    AtlasDilatePass mDilate;
    AtlasResolvePass mResolve;
    AtlasDebugViewPass mDebugView;
};

} // namespace gi::atlas
