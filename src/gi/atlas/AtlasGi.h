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
// With gi.bounces = B > 1, steps 2-3 run B times per frame: each further gather's senders
// send their direct light plus rho/pi x the E_ind just gathered (AtlasBounceSendersPass), so
// the last one's E_ind holds B bounces.
// Progressive mode (the thesis' future work, 5.4): a static scene's G-buffer is built once and
// each frame adds one more rotated sample set until atlas.target_samples; changes to lights,
// geometry or settings start over. The atlas parameterisation (AtlasBuilder) is built when
// the resolution or gutter changes, through the disk cache (AtlasCache). Animated instances
// keep their charts; their atlas vertices follow the pose (AtlasPosePass) and the G-buffer and
// sums start over whenever the geometry moves.
#pragma once

#include "gi/GiTechnique.h"
#include "gi/atlas/AtlasBounceSendersPass.h"
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

#include <optional>

namespace gi::atlas {

class AtlasGi final : public GiTechnique {
public:
    const char* name() const override { return "atlas"; }
    bool init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) override;
    bool configure(const Settings& settings, std::string& error) override;
    void update(const GiFrameInputs& in, gl::GpuProfiler& profiler) override;
    GiOutputs outputs() const override;

    // Samples per texel accumulated into the lit atlas so far (progressive mode's progress).
    int accumulatedSamples() const { return mContent.samples; }
    std::string status() const override;
    // For tests and the overlay.
    const Atlas& atlas() const { return mAtlas; }
    const AtlasBuildInfo& buildInfo() const { return mBuildInfo; }
    const AtlasTextures& textures() const { return mTextures; }
    const AtlasSenderSamplingPass& senderSampling() const { return mSenderSampling; }
    // atlas.importance: how many times the view's surfaces (view) or the scene's (surfaces)
    // were sampled since configure.
    int viewSampleTakes() const { return mViewSampleTakes; }
    int surfaceSampleTakes() const { return mSurfaceSampleTakes; }

private:
    // What the atlas layers hold, and what they were computed from: a frame redraws the
    // G-buffer only when what it shows changed, and gathers only while the sums want samples.
    struct Content {
        bool gBufferValid = false;   // direct, normal, position, albedo match the three below
        const scene::GpuScene* scene = nullptr;
        std::vector<scene::Light> lights;
        std::uint64_t geometryVersion = 0;
        // The occupancy version the sums were gathered against (none: no visibility test);
        // another one occludes differently, so the sums start over.
        std::optional<std::uint64_t> occupancyVersion;
        int samples = 0;             // samples per texel in the sums since they started over
    };
    // What one frame does, decided before any pass runs so the uniforms are written once.
    struct FramePlan {
        bool drawGBuffer = false;
        bool gather = false;         // gathers one sample set
        bool restart = false;        // ... into cleared sums
        bool inputsChanged = false;  // geometry or lights changed since the last frame
        glm::vec2 rotation{0.0f};    // Cranley-Patterson offset of that set
        int view = -1;               // ATLAS_VIEW_* of the debug view shown, -1: none
    };

    bool buildAtlasGeometry(std::string& error);
    // Allocates the atlas layers for the resolution and gi.bounces and points the passes at
    // them.
    bool allocateLayers(std::string& error);
    // The occupancy the gather tests visibility against (atlas.visibility=voxel), or nullptr.
    const OccupancyVolume* visibilityOccupancy(const GiFrameInputs& in);
    // The loop iterations of a ray through the scene's BVH (atlas.visibility=bvh), or 0.
    int visibilityBvh(const GiFrameInputs& in);
    // The near field's rays per receiver side and set: atlas.near_rays with the area estimator
    // when the frame has the BVH they walk, else 0.
    int nearRays(const GiFrameInputs& in);
    // Decides this frame's work and records in mContent what the layers will hold after it.
    FramePlan planFrame(const GiFrameInputs& in, const OccupancyVolume* occupancy);
    // The frame's AtlasUniforms: the only write of the buffer per frame.
    void writeUniforms(const FramePlan& plan, const GiFrameInputs& in);
    // Whether the area estimator's senders are drawn by an importance (atlas.importance).
    bool drawsByImportance() const;

    AtlasMesh mMesh;
    bool mBackSides = false; // some material is double-sided (AtlasTextures)
    Atlas mAtlas;
    AtlasBuildInfo mBuildInfo;
    AtlasSettings mSettings;
    ShadowSettings mShadowSettings;
    int mBounces = 1;                  // gi.bounces
    bool mGlossyMaterials = false;     // material.model=gltf: the G-buffer's light and albedo
                                       // are what the glTF BRDF reflects
    bool mConfigured = false;

    AtlasGeometry mGeometry;
    AtlasTextures mTextures;
    gl::Texture mSamples;
    gl::Buffer mUniforms;

    Content mContent;
    std::uint32_t mFrameIndex = 0;     // frames since configure: the set when not progressive
    bool mWarnedNoVisibility = false;  // a missing occupancy or BVH is reported once per configure
    bool mWarnedNoNearField = false;
    int mDebugView = -1;               // FramePlan::view of the last frame, for outputs()
    bool mConverging = false;          // GiOutputs::converging of the last frame

    // atlas.importance: the view the senders' importance was last computed for (view), and
    // whether the layer holds an importance.
    std::optional<scene::CameraView> mViewSampledFrom;
    bool mImportanceReady = false;
    int mViewSampleTakes = 0;
    int mSurfaceSampleTakes = 0;
    SurfacePoints mSurfacePoints;      // atlas.importance=surfaces: its receivers on the mesh

    // Animated instances: the atlas vertices follow GpuScene's pose (AtlasPosePass).
    bool mFollowsPose = false;
    std::uint64_t mPosedGeometry = ~std::uint64_t(0);

    AtlasPosePass mPose;
    AtlasGBufferPass mGBuffer;
    AtlasSenderSamplingPass mSenderSampling;
    AtlasBounceSendersPass mBounceSenders;
    AtlasGatherPass mGather;
    AtlasDilatePass mDilate;
    AtlasResolvePass mResolve;
    AtlasDebugViewPass mDebugViewPass;
};

} // namespace gi::atlas
