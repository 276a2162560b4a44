#include "gi/vpl/VplGi.h"

#include "gi/vpl/VplImportance.h"
#include "gi/vpl/VplSampler.h"
#include "gl/Shared.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace gi::vpl {
namespace {

// The interleave filter keeps neighbours within this fraction of the centre's view depth and
// with normals within about 25 degrees of its own.
constexpr float kFilterDepthTolerance = 0.1f;
constexpr float kFilterNormalCosine = 0.9f;
// The view's importance for the VPLs' draw is read at the centres of this many cells per side
// of the image: enough to find the surfaces the view holds, few enough that a moved camera's
// redraw costs little next to the gather (texels x samples kernel evaluations on the CPU).
constexpr int kViewSamplesPerSide = 16;

// The surface area (m^2) the light that reaches most of the scene lights: each light's texels
// cover every surface it sees once, so summing over lights would count shared surfaces twice.
float largestLitArea(const std::vector<RsmTexel>& texels, std::size_t lightCount) {
    std::vector<double> area(lightCount, 0.0);
    for (const RsmTexel& texel : texels) {
        if (texel.light >= 0 && std::size_t(texel.light) < lightCount) {
            area[std::size_t(texel.light)] += texel.area;
        }
    }
    return area.empty() ? 0.0f : float(*std::max_element(area.begin(), area.end()));
}

// The VPL_DEBUG_* view behind a technique debug view, or -1.
int debugViewOf(DebugView view) {
    switch (view) {
    case DebugView::VplPoints: return VPL_DEBUG_POINTS;
    case DebugView::VplSubset: return VPL_DEBUG_SUBSET;
    case DebugView::VplVisibility: return VPL_DEBUG_VISIBILITY;
    default: return -1;
    }
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
}

} // namespace

bool VplGi::init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) {
    (void)scene;
    mUniforms = gl::createBuffer(
            sizeof(shader::VplUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "vpl/uniforms");
    return mRsm.init(shaders, error) && mGBuffer.init(shaders, error) &&
            mGather.init(shaders, error) && mFilter.init(shaders, error) &&
            mBounce.init(shaders, error) && mSvo.init(shaders, error) &&
            mDebug.init(shaders, error);
}

bool VplGi::configure(const Settings& settings, std::string& error) {
    const VplSettings& s = settings.vpl;
    if (!SvoVisibility::validate(s, error)) return false;
    if (s.count != mSettings.count || s.rsmResolution != mSettings.rsmResolution ||
            s.bounces != mSettings.bounces || s.importance != mSettings.importance ||
            settings.glossyMaterials() != mGlossyMaterials) {
        mSource.valid = false;
    }
    mGlossyMaterials = settings.glossyMaterials();
    if (s.visibility != mSettings.visibility) mWarnedNoVisibility = false;
    mSettings = s;
    return true;
}

float VplGi::clampArea() const {
    if (mSettings.clamp > 0.0f) return mSettings.clamp;
    return kClampPerVplArea * mLitAreaPerVpl;
}

glm::ivec2 VplGi::generationCounts() const {
    if (mSettings.bounces < 2) return {mSettings.count, 0};
    const int rays = int(float(mSettings.count) * kSecondGenerationShare);
    return {std::max(mSettings.count - rays, 1), rays};
}

void VplGi::addSecondGeneration(std::vector<shader::GpuVpl>& vpls, const GiFrameInputs& in,
        gl::GpuProfiler& profiler) {
    mSecondGenerationCount = 0;
    const int rays = generationCounts().y;
    if (rays == 0) return;
    if (!in.occupancy) {
        std::fprintf(stderr, "vpl: vpl.bounces=2 needs a voxel occupancy volume and this frame "
                             "has none; the VPLs carry one bounce\n");
        return;
    }
    const std::vector<shader::GpuVpl> children =
            mBounce.execute(vpls, rays, *in.occupancy, profiler);
    vpls.insert(vpls.end(), children.begin(), children.end());
    mSecondGenerationCount = int(children.size());
}

void VplGi::renderReflectiveShadowMaps(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    const std::vector<scene::LightView> views =
            scene::lightViews(in.lights, in.scene.bounds(), mSettings.rsmResolution);
    // The RSM readback waits for the GPU, so wall clock measures its draws too.
    const auto rsmStart = std::chrono::steady_clock::now();
    mTexels = mRsm.execute(in.scene, views, mSettings.rsmResolution, mGlossyMaterials, profiler);
    mLastResampling.rsmMs = millisecondsSince(rsmStart);
    mLastResampling.rsmViews = int(views.size());
    mLastResampling.rsmTexels = mTexels.size();
    mLitAreaPerVpl = largestLitArea(mTexels, in.lights.size()) / float(generationCounts().x);
    mSource = {&in.scene, in.lights, in.scene.geometryVersion(),
            in.occupancy ? in.occupancy->version : 0, true};
}

void VplGi::drawFromTexels(const GiFrameInputs& in, gl::GpuProfiler& profiler, bool announce) {
    const int firstGeneration = generationCounts().x;
    const auto samplingStart = std::chrono::steady_clock::now();
    std::vector<shader::GpuVpl> vpls;
    {
        gl::GpuScope scope(profiler, "vpl/sample");
        if (mSettings.importance) {
            const std::vector<float> importance = viewImportance(
                    mTexels, mGBuffer.readSamples(kViewSamplesPerSide), clampArea());
            vpls = drawVpls(mTexels, importance, firstGeneration);
        } else {
            vpls = drawVpls(mTexels, firstGeneration);
        }
    }
    mDrawnFor = in.camera;
    mLastResampling.samplingMs = millisecondsSince(samplingStart);
    ++mLastResampling.resamples;
    addSecondGeneration(vpls, in, profiler);
    mVplCount = int(vpls.size());
    // Keep a buffer of at least one VPL so the gather's binding is always valid.
    if (vpls.empty()) vpls.push_back({});
    mVpls = gl::createBuffer(vpls.size() * sizeof(shader::GpuVpl), vpls.data(), 0, "vpl/vpls");
    if (!announce) return;
    std::fprintf(stderr, "vpl: %d VPLs (%d of the second generation) from %zu lit RSM texels%s, "
                         "%.4g m^2 per VPL, clamp B %.4g m^2\n",
            mVplCount, mSecondGenerationCount, mTexels.size(),
            mSettings.importance ? " by flux x the view's importance" : "",
            double(mLitAreaPerVpl), double(clampArea()));
}

const OccupancyVolume* VplGi::visibilityOccupancy(const GiFrameInputs& in) {
    if (mSettings.visibility != VPL_VISIBILITY_CASCADE) return nullptr;
    if (!in.occupancy && !mWarnedNoVisibility) {
        std::fprintf(stderr, "vpl: vpl.visibility=cascade needs a voxel occupancy volume and "
                             "this frame has none; VPLs are not occluded\n");
        mWarnedNoVisibility = true;
    }
    return in.occupancy;
}

int VplGi::visibilityBvh(const GiFrameInputs& in) {
    if (mSettings.visibility != VPL_VISIBILITY_BVH) return 0;
    if (in.bvhRayIterations <= 0 && !mWarnedNoVisibility) {
        std::fprintf(stderr, "vpl: vpl.visibility=bvh needs the scene's BVH and this frame has "
                             "none; VPLs are not occluded\n");
        mWarnedNoVisibility = true;
    }
    return in.bvhRayIterations;
}

void VplGi::writeUniforms(int visibility, int gatherOutput) {
    const int tile = mSettings.interleave ? VPL_TILE : 1;
    shader::VplUniforms u{};
    u.counts = glm::ivec4(mVplCount, tile, visibility, gatherOutput);
    u.gather = glm::vec4(clampArea(), float(tile * tile), kFilterDepthTolerance,
            kFilterNormalCosine);
    const float clampPerArea = mSettings.clamp > 0.0f ? 0.0f : kClampPerVplArea;
    u.rays = glm::vec4(mRayOffset, clampPerArea, 0.0f, 0.0f);
    glNamedBufferSubData(mUniforms.id(), 0, sizeof u, &u);
}

void VplGi::update(const GiFrameInputs& in, gl::GpuProfiler& profiler) {
    const SparseVoxelOctree* octree = nullptr;
    if (mSettings.visibility == VPL_VISIBILITY_SVO) {
        octree = mSvo.update(in.scene, mSettings, profiler);
        // Refused (over vpl.svo_budget_mb): no indirect light, failure() says why.
        mHasOutput = false;
        if (!octree) return;
    }
    const bool stale = !mSource.valid || mSource.scene != &in.scene ||
            mSource.lights != in.lights || mSource.geometryVersion != in.scene.geometryVersion() ||
            (mSettings.bounces > 1 && in.occupancy &&
                    mSource.occupancyVersion != in.occupancy->version);
    // The G-buffer first: the importance of the VPLs' draw is read from it.
    mGBuffer.execute(in.scene, in.frameUniforms, in.outputSize, profiler);
    if (stale) renderReflectiveShadowMaps(in, profiler);
    const bool viewMoved = mSettings.importance &&
            scene::viewMovedFarFrom(mDrawnFor, in.camera, glm::length(in.scene.bounds().size()));
    if (stale || viewMoved) drawFromTexels(in, profiler, stale);
    const OccupancyVolume* occupancy = visibilityOccupancy(in);
    const int bvhRayIterations = visibilityBvh(in);
    mVisibility = occupancy ? VPL_VISIBILITY_CASCADE
                  : octree  ? VPL_VISIBILITY_SVO
                  : bvhRayIterations > 0 ? VPL_VISIBILITY_BVH
                                         : VPL_VISIBILITY_NONE;
    mRayOffset = in.scene.bounds().rayOffset();
    mDebugView = debugViewOf(in.debugView);
    writeUniforms(mVisibility, mDebugView == VPL_DEBUG_VISIBILITY ? VPL_GATHER_VISIBLE_FRACTION
                                                                  : VPL_GATHER_IRRADIANCE);
    const int subsets = mSettings.interleave ? VPL_TILE * VPL_TILE : 1;
    mGather.execute({mGBuffer, mVpls, mUniforms, occupancy, octree,
                            (mVplCount + subsets - 1) / subsets, bvhRayIterations},
            profiler);
    mFilter.execute({mGather.result(), mGBuffer, mUniforms}, profiler);
    mHasOutput = mGBuffer.size().x > 0;
    if (mDebugView >= 0) {
        mDebug.execute(mDebugView, {mGBuffer, mVpls, mVplCount, mUniforms, in.frameUniforms,
                                           mFilter.result(), mSettings.debugSubset},
                profiler);
    }
}

GiOutputs VplGi::outputs() const {
    GiOutputs out;
    if (!mHasOutput) return out;
    out.indirect = &mFilter.result();
    out.size = mGBuffer.size();
    if (mDebugView >= 0) out.debugImage = &mDebug.image();
    return out;
}

VplReport VplGi::report() const {
    VplReport r = mLastResampling;
    r.count = mVplCount;
    r.secondGeneration = mSecondGenerationCount;
    r.clampArea = clampArea();
    r.clampFromScene = !(mSettings.clamp > 0.0f);
    r.visibility = mVisibility == mSettings.visibility ? visibilityName(mSettings)
                                                       : "none (no occupancy volume)";
    r.interleave = mSettings.interleave;
    r.rsmResolution = mSettings.rsmResolution;
    return r;
}

std::string VplGi::status() const {
    if (!mSvo.failure().empty()) return "vpl: " + mSvo.failure();
    const std::string visibility = visibilityName(mSettings);
    return "vpl " + std::to_string(mVplCount) + " VPLs, " +
           (mSettings.interleave ? "4x4 tiles" : "every VPL per pixel") + ", visibility " +
           visibility + ", B " + std::to_string(clampArea()) + " m^2" +
           (mSettings.bounces > 1
                           ? ", 2 bounces (" + std::to_string(mSecondGenerationCount) +
                                     " second-generation VPLs)"
                           : "");
}

} // namespace gi::vpl
