// The interface the renderer drives for a global-illumination technique. A technique turns
// the scene and its direct light into indirect irradiance E_ind (W/m^2) of the surface seen
// in each pixel; the final pass multiplies it by the surface's albedo / pi (DESIGN.md:
// L_ind = rho/pi * E_ind). With glossy materials a technique may add indirect specular
// radiance (voxel GI's specular cone). Voxel cone tracing (gi/voxel) and the atlas gather (gi/atlas)
// implement it without knowing each other.
#pragma once

#include "core/Settings.h"
#include "gi/ShadowMaps.h"
#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/Shared.h"
#include "gl/ShaderLibrary.h"
#include "scene/CameraView.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi {

// Views a technique can show instead of the final image (--output and viewer hotkeys).
enum class DebugView {
    None, VoxelAlbedo, VoxelIrradiance, VoxelNormal,
    AtlasDirect, AtlasNormal, AtlasPosition, AtlasAlbedo, AtlasIndirect, AtlasCharts,
    VplPoints, VplSubset, VplVisibility
};

// A voxel occupancy another technique can test visibility against (the atlas gather's
// atlas.visibility=voxel): the cascade layout of shaders/common/voxel_cascade.glsl.
struct OccupancyVolume {
    const gl::Texture& coverage;       // sampler3D rgba16f at BIND_TEX_VOXEL_ALBEDO, a = coverage
    const gl::Texture& planes;         // sampler3D rgba8_snorm at BIND_TEX_VOXEL_NORMAL: mean
                                       // normal and the surface's offset along it
    const gl::Texture& projectedAreas; // sampler3D rgba16f at BIND_TEX_VOXEL_IRRADIANCE: the
                                       // surfaces' area projected onto the x, y, z faces, in
                                       // face areas (rgb)
    const gl::Texture& edgeFaces;      // sampler3D rgba8_snorm at BIND_TEX_VOXEL_EDGE_FACES:
                                       // level 0's edge voxels' two faces (EdgeFacesPass.h;
                                       // none in voxel GI's own cascade, which no march walks)
    const gl::Buffer& voxelUniforms;   // VoxelUniforms (std140) at BIND_UBO_VOXEL
    std::uint64_t version = 0;         // changes whenever the occupancy is recomputed
    int levels = 1;                    // cascade levels in the textures

    // Binds what the march reads at its slots (shaders/common/voxel_visibility.glsl).
    void bind() const {
        glBindBufferBase(GL_UNIFORM_BUFFER, BIND_UBO_VOXEL, voxelUniforms.id());
        glBindTextureUnit(BIND_TEX_VOXEL_ALBEDO, coverage.id());
        glBindTextureUnit(BIND_TEX_VOXEL_NORMAL, planes.id());
        glBindTextureUnit(BIND_TEX_VOXEL_IRRADIANCE, projectedAreas.id());
        glBindTextureUnit(BIND_TEX_VOXEL_EDGE_FACES, edgeFaces.id());
    }
    // The loop iterations one segment of common/voxel_visibility.glsl runs at most: its walk's
    // steps, each finding its level among `levels`, the two ends' levels, and the edge voxels
    // it tests after the walk.
    [[nodiscard]] int visibilityLoopIterations() const {
        return 2 * levels + VOXEL_VISIBILITY_MAX_STEPS * (1 + levels) + VOXEL_VISIBILITY_MAX_EDGES;
    }
};

struct GiFrameInputs {
    const scene::GpuScene& scene;          // world-space geometry, materials, lights
    const std::vector<scene::Light>& lights;   // the same lights on the CPU
    const ShadowMaps& shadows;              // shadow maps of every light, already rendered
    const gl::Buffer& frameUniforms;       // FrameUniforms of the camera view (std140)
    const scene::CameraView& camera;
    glm::ivec2 outputSize;                 // full-resolution render size, pixels
    DebugView debugView = DebugView::None;
    const OccupancyVolume* occupancy = nullptr;   // voxel occupancy of this frame, if any
    // The scene's BVH, bound at BIND_SSBO_BVH_* (shaders/common/bvh.glsl) when a technique
    // asked for it: the most loop iterations one ray through it runs (every node and
    // triangle once), for splitting work within SHADER_LOOP_ITERATIONS; 0 when none is bound.
    int bvhRayIterations = 0;
    int bvhNodes = 0;   // that BVH's node count (0 when none is bound)
};

struct GiOutputs {
    // Screen-space indirect irradiance, RGBA16F: rgb = E_ind (W/m^2) of the surface in the
    // pixel, a = its distance along the view axis (m) for depth-aware upsampling; 0 = empty.
    const gl::Texture* indirect = nullptr;
    glm::ivec2 size{0};                    // pixels; may be smaller than the output
    // Screen-space indirect specular radiance at `size`, RGBA16F: rgb = L (W/(m^2 sr)) the
    // surface reflects towards the camera, already weighted by its specular albedo, a = view
    // depth (m); nullptr when the technique gathers diffuse light only.
    const gl::Texture* indirectSpecular = nullptr;
    // Debug views: linear radiance to show instead of the final image (full resolution,
    // RGBA32F, alpha = coverage), or nullptr.
    const gl::Texture* debugImage = nullptr;
    // The technique is accumulating its indirect light over frames after a change (of
    // geometry, lights or visibility): each frame's light supersedes the last, so a temporal
    // filter would only hold back light from before the change or noisier early frames.
    bool converging = false;
    // The technique's light comes from resources placed anew this frame (the voxel cascade
    // followed the camera to its next snap position): the image may step where the light did
    // not change, so a temporal filter fades the step in rather than clipping its history to
    // it.
    bool resampled = false;
};

class GiTechnique {
public:
    virtual ~GiTechnique() = default;
    virtual const char* name() const = 0;
    // Builds programs; false with one message on failure.
    virtual bool init(gl::ShaderLibrary& shaders, const scene::Scene& scene, std::string& error) = 0;
    // Applies settings, reallocating only what changed. False with a message if the settings
    // cannot be honoured (e.g. beyond GL limits).
    virtual bool configure(const Settings& settings, std::string& error) = 0;
    virtual void update(const GiFrameInputs& in, gl::GpuProfiler& profiler) = 0;
    virtual GiOutputs outputs() const = 0;
    // One line for the overlay: the state a user tunes against (resolution, progress).
    virtual std::string status() const { return ""; }
    // Why the settings cannot be honoured for this scene, found only while rendering (a
    // structure built from the geometry over its memory budget); empty when they can.
    virtual std::string failure() const { return ""; }
    // How far from the camera the technique gathers light (m), for controls that scale with
    // it (the viewer's maximum cone distance keys); 0 when the technique has no such bound.
    virtual float gatherReach() const { return 0.0f; }
};

} // namespace gi
