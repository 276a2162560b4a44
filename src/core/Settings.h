// Every tunable of a render, with its default, in one struct that feeds the command line
// (`--set key=value`), the viewer's widgets and the tests. The key table below is the single
// source of `voxatlas render --help`, of validation ranges, and of what `--set` accepts.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace gi {

struct ShadowSettings {
    bool enabled = true;          // shadow.enabled
    int resolution = 1024;        // shadow.resolution: texels per side of spot maps and cube faces
    int sunResolution = 4096;     // shadow.sun_resolution: texels per side of a directional
                                  // light's map, which spans the whole scene
    float normalOffset = 1.5f;    // shadow.normal_offset: texels of footprint along the normal
    float pcfRadius = 1.0f;       // shadow.pcf_radius: texels between PCF taps
    int method = 0;               // shadow.method: SHADOW_METHOD_* (0 shadowmap, 1 bvh,
                                  // 2 linespace, 3 voxel)
    int rays = 25;                // shadow.rays: shadow rays per pixel and area light (bvh,
                                  // linespace)
    bool operator==(const ShadowSettings&) const = default;
};

// The N-tree of shadow.method=linespace (SEEDS.md section 3).
struct LineSpaceSettings {
    int n = 6;                    // linespace.n: children per axis of every N-tree node
    int depth = 3;                // linespace.depth: levels below the root, the last the leaves
    bool operator==(const LineSpaceSettings&) const = default;
};

// voxel.light_read: where a diffuse cone meets a surface, the light of anisotropic voxels and
// of the light pyramid's faces is read as the cone's directions see the faces (cone, after
// Crassin et al. 2011: each face by the area it shows them) or as the faces of the surface met
// (surface): the wide read then averages only surfaces facing the way it faces, not the shaded
// sides of whatever else its texels hold. The specular cone, alone in its lobe, always reads
// as its directions see (accuracy-analysis.md).
enum LightRead : int { LIGHT_READ_CONE = 0, LIGHT_READ_SURFACE = 1 };
// voxel.cones: the diffuse cones each surface point traces (gi/voxel/ConeSet.h); PLAN is
// resolved by render::applyPlan (19 on the adaptive plan, the thesis' 9 on the fixed); DENSE
// is the quality preset's 37.
enum VoxelCones : int {
    VOXEL_CONES_PLAN = 0,
    VOXEL_CONES_THESIS = 1,
    VOXEL_CONES_RINGS = 2,
    VOXEL_CONES_DENSE = 3
};

// Voxel cone tracing (SEEDS.md section 1); defaults are the thesis' reference settings.
struct VoxelSettings {
    int resolution = 32;          // voxel.resolution: v, voxels per axis of every cascade level
    int occupancyResolution = 0;  // voxel.occupancy_resolution: voxels per axis of the occupancy
                                  // the atlas' and VPLs' visibility and voxel shadows march;
                                  // 0 = voxel.resolution
    int oneLevelLimit = 128;      // voxel.one_level_limit: the adaptive plan holds a scene in one
                                  // scene-centred level of at most this many voxels per axis
                                  // at its finest voxel, not a cascade; 0 = always a cascade
    int levels = 3;               // voxel.cascades: l, nested levels, each twice the previous edge
    int multiplier = 8;           // voxel.multiplier: voxelization raster = v x this
    int msaa = 0;                 // voxel.msaa: samples per voxelization raster pixel (0 = the
                                  // plan's: 4 adaptive, 1 fixed); a fragment stands for the
                                  // surface its covered samples hold
    bool rasterPerLevel = false;  // voxel.raster_per_level: each level rasterized over its
                                  // own extent, not the finer levels through the coarsest
    int injectResolution = 0;     // voxel.inject_resolution: light-view pixels; 0 = the
                                  // adaptive plan's (2 per finest voxel), v in a fixed plan
    bool injectFragmentMean = false;  // voxel.inject_fragment_mean: the thesis' mean over
                                      // fragments instead of flux / surface area
    float traceScale = 0.5f;      // voxel.trace_scale: cone-trace resolution / output resolution
    bool traceReuse = true;       // voxel.trace_reuse: trace one pixel of each 2x2 block per
                                  // frame while the voxels' light stands still, the others
                                  // reprojected from the previous frames (TraceReusePass.h)
    float maxDistance = 0.0f;     // voxel.max_distance: metres; 0 = edge of the coarsest level
    float extent = 0.0f;          // voxel.extent: finest level edge (m); 0 = from the scene
    bool coverageMaxAxis = true;  // voxel.coverage_max_axis: coarse coverage from the most
                                  // opaque axis instead of the thesis' mean (which halves a
                                  // one-voxel wall's opacity per level and loses its light)
    bool coarsePlanes = true;     // voxel.coarse_planes: cone tracing takes a coarser level's
                                  // voxel for one plane (0: only level 0, voxel_plane.glsl)
    bool anisotropic = false;     // voxel.anisotropic: each voxel as seen from its 6 faces,
                                  // coarser levels composited front to back per face
    int lightRead = LIGHT_READ_CONE; // voxel.light_read: which faces of the voxels (or, for
                                  // isotropic ones, of the light pyramid) a cone's light
                                  // read takes where it meets a surface
    int pyramidMips = -1;         // voxel.pyramid_mips: widest pyramid mip cone tracing reads
                                  // (-1 = all; wide texels average across walls)
    bool sceneCentred = false;    // voxel.scene_centred: cascade centred on the scene's bounds
                                  // (finest level holding the scene) instead of the camera
    // Not a key of its own: voxelization also sums the surfaces' area projected onto the three
    // axes (the visibility marches' occupancy, FrameRenderer::updateOccupancy).
    bool projectedAreas = false;
    bool clampCentre = false;     // voxel.clamp_centre: the camera-centred cascade's centre
                                  // kept inside the scene's bounds (the adaptive plan's choice)
    float size = 0.0f;            // voxel.size: finest voxel edge (m) of the adaptive plan;
                                  // 0 = the scene's shortest side / voxel.resolution
    int cones = VOXEL_CONES_PLAN; // voxel.cones: the plan's, 9 (the thesis') or 19 diffuse
                                  // cones
    bool coneInterleave = false;  // voxel.cone_interleave: neighbouring pixels trace
                                  // alternate halves of the 19 cones' rings (merged by the
                                  // filter)
    float coneAngle = 0.0f;       // voxel.cone_angle: full aperture of each diffuse cone,
                                  // degrees; 0 = the cone set's own (45 or 37.3)
    float stepFactor = 1.0f;      // voxel.step: sample spacing in cone diameters (thesis: 1)
    float footprint = 0.6f;       // voxel.footprint: texel width of the light pyramid mip a
                                  // cone reads, in cone diameters (thesis: 1; a trilinear
                                  // read of texels one diameter wide averages over about
                                  // twice the cone's footprint, cone_tracing.glsl)
    float coneOffset = 1.0f;      // voxel.cone_offset: finest voxels between a surface and its
                                  // cones' origin (at least one voxel of the level holding
                                  // it), the thesis' minimum distance
    float walkStart = 0.0f;       // voxel.walk_start: voxels of the level holding a cone's
                                  // origin between the origin and the first voxel its walk
                                  // reads, on a one-level volume (the thesis' 1; a cascade
                                  // always starts one voxel out)
    bool falloff = false;         // voxel.falloff: the thesis' 1/(1+d^2) sample attenuation
    bool depthUpsample = true;    // voxel.upsample_depth: depth-aware (1) or bilinear (0)
    bool planeUpsample = false;   // voxel.upsample_plane: the depth-aware upsampling also
                                  // weighs each texel by its distance from the pixel's plane
                                  // (measured, not yet the default: accuracy-analysis.md)
    bool jitter = true;           // voxel.jitter: turn the cone ring per pixel (RingDither.h)
    bool jitterElevation = false; // voxel.jitter_elevation: the same dither moves each ring's
                                  // cones within its band (ConeSet.h)
    int filterRadius = 2;         // voxel.filter: edge-aware smoothing radius, texels of a
                                  // trace at scale 0.5 (scaled with voxel.trace_scale)
    int debugLevel = 0;           // voxel.debug_level: cascade level shown by debug views
    bool cache = true;            // voxel.cache: keep the static voxelization and the injected
                                  // light while their inputs stay the same (0 = every pass
                                  // every frame, as in the thesis)
    bool operator==(const VoxelSettings&) const = default;
};

// Texture-atlas GI (SEEDS.md section 2, gi/atlas); samples = 100 is the thesis' setting.
struct AtlasSettings {
    int resolution = 1024;        // atlas.resolution: texels per side of the atlas
    float texelSize = 0.0f;       // atlas.texel_size: texel edge (m) of the adaptive plan;
                                  // 0 = half the plan's finest voxel
    int samples = 100;            // atlas.samples: N, Hammersley points per gather set
    int estimator = 0;            // atlas.estimator: ATLAS_ESTIMATOR_* (0 area, 1 merz2010)
    int visibility = 0;           // atlas.visibility: ATLAS_VISIBILITY_* (0 none, 1 voxel, 2 bvh)
    bool progressive = true;      // atlas.progressive: accumulate sets while nothing changes
    int targetSamples = 1024;     // atlas.target_samples: stop accumulating at this count
    bool rotate = true;           // atlas.rotate: new Cranley-Patterson offset per set
    int gutter = 2;               // atlas.gutter: empty texels between charts
    bool filter = true;           // atlas.filter: each texel's E_ind averaged over the 3x3
                                  // texels of its own surface (shaders/atlas/dilate.frag)
    int importance = 2;           // atlas.importance: ATLAS_IMPORTANCE_* (0 power, 1 view,
                                  // 2 surfaces): the area estimator draws senders by power, or by
                                  // power x what the camera's view can receive of it (the atlas'
                                  // light then depends on the view in its noise), or x what the
                                  // scene's surfaces can receive of it (it does not)
    int nearRays = 4;             // atlas.near_rays: directions per receiver side and set that
                                  // count the senders within atlas.near_reach (near_field.glsl);
                                  // 0 = none
    float nearReach = 6.0f;       // atlas.near_reach: that reach in texel edges, at least the
                                  // 2 within which the estimator's 1/r^2 stops growing; 6 also
                                  // takes the senders within a voxel or two, which the voxel
                                  // march blocks most wrongly, and further gains little
                                  // (docs/accuracy-analysis.md)
    bool cache = true;            // atlas.cache: keep built atlases on disk
    bool operator==(const AtlasSettings&) const = default;
};

// Many-lights GI with virtual point lights (SEEDS.md section 4, gi/vpl).
struct VplSettings {
    int count = 1024;             // vpl.count: VPLs drawn from the reflective shadow maps
    float clamp = 0.0f;           // vpl.clamp: B of 1 / max(B, r^2) (m^2); 0 = from the scene
                                  // (VplGi.h: a fixed fraction of its diagonal, squared)
    int visibility = 1;           // vpl.visibility: VPL_VISIBILITY_* (0 none, 1 cascade, 2 svo)
    int svoResolution = 128;      // vpl.svo_resolution: octree leaves per side (power of two)
    int svoBudgetMb = 256;        // vpl.svo_budget_mb: the octree's nodes may take this much
    bool interleave = true;       // vpl.interleave: 4x4 tiles, each pixel 1/16 of the VPLs
    bool importance = true;       // vpl.importance: draw VPLs by flux x what the view receives
    int rsmResolution = 128;      // vpl.rsm_resolution: pixels per side of a light's RSM view
    int bounces = 1;              // vpl.bounces: 2 adds VPLs where the first ones' light lands
    int debugSubset = 0;          // vpl.debug_subset: the pixel class vpl-subset highlights
    bool operator==(const VplSettings&) const = default;
};

// Temporal reprojection of the GI technique's indirect irradiance (render/TemporalFilter.h).
struct TemporalSettings {
    bool filter = true;           // gi.temporal_filter: blend each frame's indirect irradiance
                                  // with the previous frames' reprojected into this view (a
                                  // single frame, or a still camera's converged one, is the
                                  // technique's own image)
    float blend = 0.2f;           // gi.temporal_blend: weight of the new frame once a pixel's
                                  // history is long enough (1 = no history)
    bool clamp = true;            // gi.temporal_clamp: history clipped to the new frame's
                                  // 3x3 mean +- one deviation, which cuts trails behind
                                  // moving objects
    float blendMoving = 0.5f;     // gi.temporal_blend_moving: the new frame's least weight on
                                  // frames whose geometry moved (an animation): light that
                                  // changes a little each frame stays inside the clip, and an
                                  // average of weight 0.2 lags it by four frames
    bool operator==(const TemporalSettings&) const = default;
};

// reference.pixel, in the order of its choices.
enum ReferencePixel : int { kReferencePixelArea = 0, kReferencePixelCentre = 1 };

// The Embree ground-truth renderer (src/reference/); see ReferenceRenderer.h.
struct ReferenceSettings {
    int spp = 64;                 // reference.spp: paths per pixel, jittered over the pixel square
    int bounces = 1;              // reference.bounces: indirect bounces (1 = direct + one bounce)
    int seed = 1;                 // reference.seed: seeds every pixel's random sequence
    // reference.pixel: kReferencePixelArea averages each pixel's square, as a camera's sensor
    // would; kReferencePixelCentre sends every path through the pixel's centre, the point a
    // rasterizer's one sample per pixel shades, so GI is scored without the silhouettes'
    // aliasing (a pixel straddling an edge is part block, part wall only in the area form).
    int pixel = kReferencePixelArea;
    int threads = 0;              // reference.threads: worker threads, 0 = all cores
    // Not a key of its own: the material settings' glossyMaterials(), filled in by
    // Settings::pathTracer() (the reference cache keys glossy renders apart).
    bool glossy = false;          // glTF metallic-roughness BRDF instead of Lambert
    bool operator==(const ReferenceSettings&) const = default;
};

// material.model: the BRDF of every surface. Phong: Lambertian (rho = base colour) in the path
// tracer and every GPU pass, plus, on the GPU's direct light only, a Blinn-Phong highlight of
// strength material.specular (today's look, not part of the reference). glTF: the glTF
// metallic-roughness BRDF (Lambert x (1 - metallic) + GGX) in the path tracer, in the GPU's
// direct light in every mode and, in voxel GI, a specular cone. material.specular = 0 turns
// every specular term off in either model: Lambertian everywhere, the accuracy comparisons.
enum MaterialModel : int { MATERIAL_PHONG = 0, MATERIAL_GLTF = 1 };

// render.plan: where the GI resources' sizes come from (render/ResourcePlan.h).
enum PlanMode : int { PLAN_FIXED = 0, PLAN_ADAPTIVE = 1 };

struct Settings {
    // Rendering.
    int plan = PLAN_ADAPTIVE;          // render.plan: adaptive (cascades and atlas sized from
                                       // the scene) or fixed (the thesis' settings as given)
    int supersample = 1;        // render.supersample: pixels averaged per output pixel per axis
    int msaa = 1;               // render.msaa: samples a pixel of the final shading pass, each
                                // surface shaded once per pixel and averaged by the area its
                                // samples cover (1 = one surface a pixel, at its centre)
    int frames = 1;             // render.frames: frames rendered; timings are their median
    int warmupFrames = 0;       // render.warmup: frames rendered and discarded before timing
    bool glDebug = false;       // gl.debug: KHR_debug messages to stderr
    bool depthPrepass = true;   // render.depth_prepass: shade each pixel once
    // Materials (see MaterialModel).
    int materialModel = MATERIAL_PHONG;   // material.model
    float specular = 0.04f;     // material.specular: Blinn-Phong ks; 0 switches every specular
                                // term off (with material.model=gltf, any other value on)
    float shininess = 64.0f;    // material.shininess: Blinn-Phong exponent n
    // Indirect light.
    int giBounces = 1;          // gi.bounces: bounces of indirect light voxel and atlas GI
                                // follow (1: light reflected once, the thesis)
    ShadowSettings shadow;
    LineSpaceSettings lineSpace;
    VoxelSettings voxel;
    AtlasSettings atlas;
    VplSettings vpl;
    TemporalSettings temporal;
    ReferenceSettings reference;
    // Viewer.
    float frameBudgetMs = 100.0f;  // view.frame_budget_ms: while the camera moves, the render
                                   // resolution drops to keep frames near this (0 = off)
    bool screenshotUi = false;  // view.screenshot_ui (hidden): --screenshot includes the overlay

    // The glTF metallic-roughness BRDF is on (path tracer and GPU alike).
    bool glossyMaterials() const { return materialModel == MATERIAL_GLTF && specular > 0.0f; }
    // The path tracer's settings, with the materials the GPU renders.
    ReferenceSettings pathTracer() const {
        ReferenceSettings settings = reference;
        settings.glossy = glossyMaterials();
        return settings;
    }
};

struct SettingSpec {
    std::string key;
    std::string help;
    std::function<std::string(const Settings&)> get;
    // Parses and range-checks `value`; on failure writes why (without the key) and returns false.
    std::function<bool(Settings&, const std::string&, std::string&)> set;
    bool hidden = false;   // accepted by --set but left out of --help (developer switches)
};

[[nodiscard]] const std::vector<SettingSpec>& settingSpecs();

// Applies "key=value". Errors name the key and the accepted range.
[[nodiscard]] bool applySetting(Settings& settings, const std::string& assignment,
        std::string& error);

// "key  default  help" lines for --help, aligned.
[[nodiscard]] std::string settingsHelp();

} // namespace gi
