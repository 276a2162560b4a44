#include "core/Settings.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gi {
namespace {

std::string formatFloat(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(value));
    return text;
}

template <class Access>
SettingSpec intSetting(std::string key, std::string help, int min, int max, Access access) {
    return {std::move(key), std::move(help) + " [" + std::to_string(min) + ".." + std::to_string(max) + "]",
            [access](const Settings& s) { return std::to_string(access(const_cast<Settings&>(s))); },
            [access, min, max](Settings& s, const std::string& text, std::string& error) {
                int value = 0;
                const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
                if (ec != std::errc() || end != text.data() + text.size()) {
                    error = "'" + text + "' is not an integer";
                    return false;
                }
                if (value < min || value > max) {
                    error = text + " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]";
                    return false;
                }
                access(s) = value;
                return true;
            }};
}

// An int setting that is a power of two in [min, max], or also 0 (follow another setting)
// when `zero` says so.
enum class Zero { Refused, Allowed };
template <class Access>
SettingSpec powerOfTwoSetting(std::string key, std::string help, int min, int max, Zero zero,
        Access access) {
    SettingSpec spec = intSetting(std::move(key), std::move(help),
            zero == Zero::Allowed ? 0 : min, max, access);
    spec.set = [parse = spec.set, access, min, zero](Settings& s, const std::string& text,
                       std::string& error) {
        Settings parsed = s;
        if (!parse(parsed, text, error)) return false;
        const int value = access(parsed);
        if (value == 0 && zero == Zero::Allowed) {
            access(s) = value;
            return true;
        }
        if (value < min || (value & (value - 1)) != 0) {
            error = text + " is not a power of two from " + std::to_string(min) +
                    (zero == Zero::Allowed ? " (or 0)" : "");
            return false;
        }
        access(s) = value;
        return true;
    };
    return spec;
}

template <class Access>
SettingSpec floatSetting(std::string key, std::string help, float min, float max, Access access) {
    return {std::move(key), std::move(help) + " [" + formatFloat(min) + ".." + formatFloat(max) + "]",
            [access](const Settings& s) { return formatFloat(access(const_cast<Settings&>(s))); },
            [access, min, max](Settings& s, const std::string& text, std::string& error) {
                float value = 0.0f;
                const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
                if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
                    error = "'" + text + "' is not a finite number";
                    return false;
                }
                if (value < min || value > max) {
                    error = text + " is outside [" + formatFloat(min) + ", " + formatFloat(max) + "]";
                    return false;
                }
                access(s) = value;
                return true;
            }};
}

template <class Access>
SettingSpec boolSetting(std::string key, std::string help, Access access) {
    return {std::move(key), std::move(help) + " [0|1]",
            [access](const Settings& s) { return std::string(access(const_cast<Settings&>(s)) ? "1" : "0"); },
            [access](Settings& s, const std::string& text, std::string& error) {
                if (text == "1" || text == "true" || text == "on") access(s) = true;
                else if (text == "0" || text == "false" || text == "off") access(s) = false;
                else {
                    error = "'" + text + "' is not 0 or 1";
                    return false;
                }
                return true;
            }};
}

// An int setting named by words on the command line ("area", "merz2010"); the number
// itself is accepted too. `names[i]` is the word for value i.
template <class Access>
SettingSpec choiceSetting(std::string key, std::string help, std::vector<std::string> names,
        Access access) {
    std::string choices;
    for (const std::string& name : names) choices += (choices.empty() ? "" : "|") + name;
    return {std::move(key), std::move(help) + " [" + choices + "]",
            [access, names](const Settings& s) {
                const int value = access(const_cast<Settings&>(s));
                return value >= 0 && value < int(names.size()) ? names[std::size_t(value)]
                                                               : std::to_string(value);
            },
            [access, names, choices](Settings& s, const std::string& text, std::string& error) {
                for (std::size_t i = 0; i < names.size(); ++i) {
                    if (text == names[i] || text == std::to_string(i)) {
                        access(s) = int(i);
                        return true;
                    }
                }
                error = "'" + text + "' is not one of " + choices;
                return false;
            }};
}

SettingSpec hidden(SettingSpec spec) {
    spec.hidden = true;
    return spec;
}

} // namespace

const std::vector<SettingSpec>& settingSpecs() {
    static const std::vector<SettingSpec> specs = {
        choiceSetting("render.plan",
                "GI resources sized from the scene (adaptive: voxel.size, atlas.texel_size) or as "
                "set (fixed, the thesis' allocation); setting a key marked 'fixed plan' selects "
                "fixed; `voxatlas info` shows the plan",
                {"fixed", "adaptive"}, [](Settings& s) -> int& { return s.plan; }),
        intSetting("render.supersample", "samples per pixel per axis, box-averaged", 1, 4,
                [](Settings& s) -> int& { return s.supersample; }),
        powerOfTwoSetting("render.msaa",
                "samples a pixel of the final shading pass (power of two; 1 = off): a pixel "
                "where surfaces meet averages them by the area each covers, as the path "
                "tracer's pixel does",
                1, 8, Zero::Refused, [](Settings& s) -> int& { return s.msaa; }),
        intSetting("render.frames", "frames rendered; --timings reports their median", 1, 1000,
                [](Settings& s) -> int& { return s.frames; }),
        intSetting("render.warmup", "frames rendered before timing starts", 0, 1000,
                [](Settings& s) -> int& { return s.warmupFrames; }),
        boolSetting("render.depth_prepass", "depth-only pass first, so each pixel is shaded once",
                [](Settings& s) -> bool& { return s.depthPrepass; }),
        boolSetting("gl.debug", "log KHR_debug messages to stderr",
                [](Settings& s) -> bool& { return s.glDebug; }),
        choiceSetting("material.model",
                "surface BRDF: phong = Lambertian, plus a Blinn-Phong highlight of strength "
                "material.specular in the GPU's direct light only (the path tracer stays "
                "Lambertian); gltf = glTF metallic-roughness (Lambert x (1 - metallic) + GGX) in "
                "the path tracer and on the GPU: direct light in every mode, a specular cone in "
                "voxel GI; every GI mode's surfaces send on what the glTF BRDF reflects (the atlas and "
                "VPL GI reflect only the diffuse term of what they gather)",
                {"phong", "gltf"}, [](Settings& s) -> int& { return s.materialModel; }),
        floatSetting("material.specular",
                "Blinn-Phong specular strength ks; 0 = Lambert only in every model and mode (the "
                "accuracy comparisons), with material.model=gltf any other value turns the glTF "
                "specular on",
                0.0f, 1.0f, [](Settings& s) -> float& { return s.specular; }),
        floatSetting("material.shininess", "Blinn-Phong exponent n", 1.0f, 4096.0f,
                [](Settings& s) -> float& { return s.shininess; }),
        boolSetting("shadow.enabled", "shadow maps for every light",
                [](Settings& s) -> bool& { return s.shadow.enabled; }),
        intSetting("shadow.resolution", "texels per side of each spot light's map and cube face", 16, 8192,
                [](Settings& s) -> int& { return s.shadow.resolution; }),
        intSetting("shadow.sun_resolution",
                "texels per side of each directional light's map (it spans the whole scene)", 16, 8192,
                [](Settings& s) -> int& { return s.shadow.sunResolution; }),
        floatSetting("shadow.normal_offset", "lookup offset along the normal, in shadow texels",
                0.0f, 16.0f, [](Settings& s) -> float& { return s.shadow.normalOffset; }),
        floatSetting("shadow.pcf_radius", "spacing of the PCF taps, in shadow texels", 0.0f, 8.0f,
                [](Settings& s) -> float& { return s.shadow.pcfRadius; }),
        choiceSetting("shadow.method",
                "shadows of the direct light the camera sees: maps from each light's centre, "
                "rays through the scene's BVH, rays through the line space of an N-tree "
                "(linespace.n, linespace.depth), or one cone per light through a voxel "
                "occupancy of the scene",
                {"shadowmap", "bvh", "linespace", "voxel"}, [](Settings& s) -> int& { return s.shadow.method; }),
        intSetting("shadow.rays",
                "shadow rays per pixel and area light with shadow.method=bvh or linespace", 1, 1024,
                [](Settings& s) -> int& { return s.shadow.rays; }),
        intSetting("linespace.n", "children per axis of each N-tree node (shadow.method=linespace)",
                4, 10, [](Settings& s) -> int& { return s.lineSpace.n; }),
        intSetting("linespace.depth",
                "N-tree levels below the root, the last the leaf voxels (shadow.method=linespace)",
                2, 4, [](Settings& s) -> int& { return s.lineSpace.depth; }),
        intSetting("gi.bounces",
                "bounces of indirect light in voxel and atlas GI: 1 = light reflected once (the "
                "thesis), each more gathers the last bounce's light again",
                1, 16, [](Settings& s) -> int& { return s.giBounces; }),
        powerOfTwoSetting("voxel.resolution", "voxels per axis of each cascade level (power of two)",
                4, 256, Zero::Refused, [](Settings& s) -> int& { return s.voxel.resolution; }),
        powerOfTwoSetting("voxel.one_level_limit",
                "render.plan=adaptive: a scene that one scene-centred level of at most this many "
                "voxels per axis holds at the finest voxel the plan needs, or at up to twice it, "
                "gets that level instead of a camera-centred cascade (power of two; 0 = always a "
                "cascade)",
                4, 256, Zero::Allowed, [](Settings& s) -> int& { return s.voxel.oneLevelLimit; }),
        powerOfTwoSetting("voxel.occupancy_resolution",
                "voxels per axis of the occupancy that atlas.visibility=voxel, "
                "vpl.visibility=cascade and shadow.method=voxel march (power of two; 0 = "
                "voxel.resolution)",
                4, 256, Zero::Allowed,
                [](Settings& s) -> int& { return s.voxel.occupancyResolution; }),
        intSetting("voxel.cascades",
                "nested cascade levels, each doubling the edge (fixed plan)", 1, 8,
                [](Settings& s) -> int& { return s.voxel.levels; }),
        intSetting("voxel.multiplier", "voxelization raster resolution / voxel resolution", 1, 16,
                [](Settings& s) -> int& { return s.voxel.multiplier; }),
        powerOfTwoSetting("voxel.msaa",
                "samples per voxelization raster pixel (power of two; 0 = the plan's: 4 with "
                "render.plan=adaptive, 1 with fixed): a surface that covers a sample but not "
                "the pixel's centre is voxelized too, with the area of its samples",
                1, 8, Zero::Allowed, [](Settings& s) -> int& { return s.voxel.msaa; }),
        boolSetting("voxel.raster_per_level",
                "rasterize each cascade level over its own extent at voxel.resolution x "
                "voxel.multiplier (0: one raster over the coarsest level, which gives the finest "
                "of L levels 2^(L-1) / voxel.multiplier raster pixels per voxel edge)",
                [](Settings& s) -> bool& { return s.voxel.rasterPerLevel; }),
        intSetting("voxel.inject_resolution", "light-view resolution for injection (0 = four pixels per finest voxel across the scene with render.plan=adaptive, voxel.resolution with fixed)",
                0, 4096, [](Settings& s) -> int& { return s.voxel.injectResolution; }),
        boolSetting("voxel.inject_fragment_mean",
                "inject the thesis' mean over light fragments (0 = flux / surface area)",
                [](Settings& s) -> bool& { return s.voxel.injectFragmentMean; }),
        floatSetting("voxel.trace_scale", "cone-trace resolution per axis / output resolution",
                0.0625f, 1.0f, [](Settings& s) -> float& { return s.voxel.traceScale; }),
        boolSetting("voxel.trace_reuse",
                "trace one pixel of each 2x2 block per frame while the voxels' light stands "
                "still, the other three reprojected from the last frames",
                [](Settings& s) -> bool& { return s.voxel.traceReuse; }),
        floatSetting("voxel.max_distance", "cone length in metres (0 = to the coarsest level's edge)",
                0.0f, 1e6f, [](Settings& s) -> float& { return s.voxel.maxDistance; }),
        floatSetting("voxel.extent",
                "finest level edge in metres (0 = derived from the scene; fixed plan)", 0.0f, 1e6f,
                [](Settings& s) -> float& { return s.voxel.extent; }),
        floatSetting("voxel.size",
                "finest voxel edge in metres for render.plan=adaptive (0 = the scene's shortest "
                "side / voxel.resolution)",
                0.0f, 1e6f, [](Settings& s) -> float& { return s.voxel.size; }),
        boolSetting("voxel.clamp_centre",
                "keep the camera-centred cascade's centre inside the scene's bounds (fixed plan)",
                [](Settings& s) -> bool& { return s.voxel.clampCentre; }),
        boolSetting("voxel.coverage_max_axis",
                "propagate coverage as the most opaque axis' opacity (walls stay opaque)",
                [](Settings& s) -> bool& { return s.voxel.coverageMaxAxis; }),
        boolSetting("voxel.coarse_planes",
                "cone tracing meets a coarser level's voxel at its mean plane (0 = only level 0's)",
                [](Settings& s) -> bool& { return s.voxel.coarsePlanes; }),
        boolSetting("voxel.anisotropic",
                "six directional values per voxel, filtered front to back per face (Crassin 2011)",
                [](Settings& s) -> bool& { return s.voxel.anisotropic; }),
        choiceSetting("voxel.light_read",
                "where a diffuse cone meets a surface, read the faces of the light it meets "
                "(anisotropic voxels, and the light pyramid of isotropic ones) as the cone's "
                "directions see them (cone) or as the surface met faces (surface: its wide read "
                "leaves out the shaded sides of what else its texels hold); the specular cone "
                "reads as its directions see",
                {"cone", "surface"}, [](Settings& s) -> int& { return s.voxel.lightRead; }),
        intSetting("voxel.pyramid_mips",
                "widest mip of the light pyramid above the coarsest level cone tracing reads "
                "(-1 = all)",
                -1, 8, [](Settings& s) -> int& { return s.voxel.pyramidMips; }),
        boolSetting("voxel.scene_centred",
                "centre the cascade on the scene (finest level holds it) instead of the camera "
                "(fixed plan)",
                [](Settings& s) -> bool& { return s.voxel.sceneCentred; }),
        choiceSetting("voxel.cones",
                "diffuse cones per surface point: 9 (the thesis: one on the normal, eight at 50 "
                "degrees), 19 (one on the normal, 6 at 27 and 12 at 56 degrees, each 1/19 of "
                "the cosine-weighted hemisphere), 37 (three rings of 6, 12 and 18, each 1/37: "
                "the quality preset's), or the plan's (19 on the adaptive plan, 9 on the fixed)",
                {"plan", "9", "19", "37"}, [](Settings& s) -> int& { return s.voxel.cones; }),
        boolSetting("voxel.cone_interleave",
                "with 19 cones, neighbouring pixels trace alternate halves of the cone rings and "
                "the filter merges them (10 cones per pixel, about half the trace); needs "
                "voxel.filter; a moving camera's trace reuse strays further from the full trace",
                [](Settings& s) -> bool& { return s.voxel.coneInterleave; }),
        floatSetting("voxel.cone_angle",
                "full aperture of each diffuse cone, degrees (0 = the cone set's own: 45 for 9 "
                "cones, 37.3 for 19)",
                0.0f, 90.0f, [](Settings& s) -> float& { return s.voxel.coneAngle; }),
        floatSetting("voxel.step", "cone sample spacing in cone diameters", 0.1f, 2.0f,
                [](Settings& s) -> float& { return s.voxel.stepFactor; }),
        floatSetting("voxel.footprint",
                "texel width of the light pyramid mip a cone reads, in cone diameters "
                "(thesis: 1)",
                0.25f, 2.0f, [](Settings& s) -> float& { return s.voxel.footprint; }),
        floatSetting("voxel.cone_offset",
                "finest voxels between a surface and the origin of its cones, at least one voxel "
                "of the level holding it (the thesis' minimum distance)",
                0.5f, 4.0f, [](Settings& s) -> float& { return s.voxel.coneOffset; }),
        floatSetting("voxel.walk_start",
                "voxels between a cone's origin and where its walk starts, on a one-level volume "
                "(the thesis' 1 skips the surfaces within a voxel of the origin; a cascade "
                "always starts 1 voxel out)",
                0.0f, 2.0f, [](Settings& s) -> float& { return s.voxel.walkStart; }),
        boolSetting("voxel.falloff", "apply the thesis' 1/(1+d^2) attenuation to cone samples",
                [](Settings& s) -> bool& { return s.voxel.falloff; }),
        boolSetting("voxel.upsample_depth", "depth-aware upsampling of the traced indirect light",
                [](Settings& s) -> bool& { return s.voxel.depthUpsample; }),
        boolSetting("voxel.upsample_plane",
                "with voxel.upsample_depth, each texel of the indirect light is also weighted by "
                "its distance from the pixel's own plane, so light does not cross edges where "
                "two surfaces meet at one depth",
                [](Settings& s) -> bool& { return s.voxel.planeUpsample; }),
        boolSetting("voxel.cache",
                "voxelize static geometry once per cascade placement and reuse the injected light "
                "while lights and geometry stay the same (0 = every pass every frame)",
                [](Settings& s) -> bool& { return s.voxel.cache; }),
        boolSetting("voxel.jitter",
                "turn the cone ring per pixel in a 2x2 or 4x4 pattern of quads, a whole period "
                "within voxel.filter's window (none where the window is 3x3; 4x4 pixels without "
                "the filter)",
                [](Settings& s) -> bool& { return s.voxel.jitter; }),
        boolSetting("voxel.jitter_elevation",
                "with voxel.jitter, the same dither also moves each ring's cones up and down "
                "within the part of the hemisphere the ring stands for (the quality preset's)",
                [](Settings& s) -> bool& { return s.voxel.jitterElevation; }),
        intSetting("voxel.filter",
                "edge-aware smoothing radius of the traced result (texels at voxel.trace_scale=0.5, "
                "scaled with the trace scale)", 0, 4,
                [](Settings& s) -> int& { return s.voxel.filterRadius; }),
        intSetting("voxel.debug_level", "cascade level shown by the voxel debug views", 0, 7,
                [](Settings& s) -> int& { return s.voxel.debugLevel; }),
        intSetting("atlas.resolution", "texels per side of the GI atlas (fixed plan)", 16, 4096,
                [](Settings& s) -> int& { return s.atlas.resolution; }),
        floatSetting("atlas.texel_size",
                "atlas texel edge in metres for render.plan=adaptive (0 = half the finest voxel)",
                0.0f, 1e6f, [](Settings& s) -> float& { return s.atlas.texelSize; }),
        intSetting("atlas.samples", "Hammersley samples per atlas texel and set (thesis: 100)", 1,
                4096, [](Settings& s) -> int& { return s.atlas.samples; }),
        choiceSetting("atlas.estimator",
                "gather weighting: area form (converges) or the thesis' 2 pi / N",
                {"area", "merz2010"}, [](Settings& s) -> int& { return s.atlas.estimator; }),
        choiceSetting("atlas.visibility",
                "occlusion between atlas texels: none, the voxel occupancy, or rays through the "
                "scene's triangles (bvh, exact and slower)",
                {"none", "voxel", "bvh"},
                [](Settings& s) -> int& { return s.atlas.visibility; }),
        boolSetting("atlas.progressive", "accumulate sample sets over frames while nothing changes",
                [](Settings& s) -> bool& { return s.atlas.progressive; }),
        intSetting("atlas.target_samples", "progressive mode stops at this many samples", 1, 1 << 20,
                [](Settings& s) -> int& { return s.atlas.targetSamples; }),
        boolSetting("atlas.rotate", "Cranley-Patterson rotation of each new sample set",
                [](Settings& s) -> bool& { return s.atlas.rotate; }),
        boolSetting("atlas.filter",
                "average each texel's indirect light with its 3x3 neighbours on the same surface",
                [](Settings& s) -> bool& { return s.atlas.filter; }),
        choiceSetting("atlas.importance",
                "draw the gather's senders by power alone, x what the camera's view can receive "
                "of it (less noise in view, more elsewhere: the lit atlas then depends on the "
                "view), or x what the scene's surfaces can receive of it",
                {"power", "view", "surfaces"},
                [](Settings& s) -> int& { return s.atlas.importance; }),
        intSetting("atlas.near_rays",
                "rays per receiver side and set through the scene's triangles that count the "
                "senders within atlas.near_reach, which the area estimator's 1/r^2 clamp and the "
                "voxel march get wrong (0 = none: the estimator counts them)",
                0, 1024, [](Settings& s) -> int& { return s.atlas.nearRays; }),
        floatSetting("atlas.near_reach",
                "how far the near field's rays count senders, in texel edges (at least the 2 of "
                "the estimator's 1/r^2 clamp)",
                2.0f, 64.0f, [](Settings& s) -> float& { return s.atlas.nearReach; }),
        intSetting("atlas.gutter", "empty texels between atlas charts", 2, 16,
                [](Settings& s) -> int& { return s.atlas.gutter; }),
        boolSetting("atlas.cache", "keep built atlases in the cache directory",
                [](Settings& s) -> bool& { return s.atlas.cache; }),
        intSetting("vpl.count", "virtual point lights drawn by flux from the lights' RSMs", 1,
                1 << 20, [](Settings& s) -> int& { return s.vpl.count; }),
        floatSetting("vpl.clamp",
                "B of the VPL gather's 1/max(B, r^2), m^2 (0 = from the scene's size)", 0.0f,
                1e12f, [](Settings& s) -> float& { return s.vpl.clamp; }),
        choiceSetting("vpl.visibility",
                "occlusion between shading points and VPLs: none, the voxel occupancy "
                "(cascade), the sparse voxel octree (svo), or rays through the scene's "
                "triangles (bvh, exact)",
                {"none", "cascade", "svo", "bvh"}, [](Settings& s) -> int& { return s.vpl.visibility; }),
        powerOfTwoSetting("vpl.svo_resolution",
                "leaf voxels per side of the sparse voxel octree over the scene (power of two)",
                16, 1024, Zero::Refused, [](Settings& s) -> int& { return s.vpl.svoResolution; }),
        intSetting("vpl.svo_budget_mb", "most memory the sparse voxel octree's nodes may take, MiB",
                1, 4096, [](Settings& s) -> int& { return s.vpl.svoBudgetMb; }),
        boolSetting("vpl.interleave", "4x4 interleaved VPL subsets merged by a geometry-aware filter",
                [](Settings& s) -> bool& { return s.vpl.interleave; }),
        boolSetting("vpl.importance",
                "draw VPLs by flux times how much of their light the camera's view can receive "
                "(redrawn as the camera moves; 0 = by flux alone)",
                [](Settings& s) -> bool& { return s.vpl.importance; }),
        intSetting("vpl.rsm_resolution", "pixels per side of each reflective shadow map view", 8,
                2048, [](Settings& s) -> int& { return s.vpl.rsmResolution; }),
        intSetting("vpl.bounces",
                "bounces the VPLs carry: 2 adds VPLs where rays from the first ones meet the "
                "voxels (a share of vpl.count)",
                1, 2, [](Settings& s) -> int& { return s.vpl.bounces; }),
        intSetting("vpl.debug_subset",
                "pixel class (x mod 4) + 4 (y mod 4) whose VPLs --output vpl-subset highlights",
                0, 15, [](Settings& s) -> int& { return s.vpl.debugSubset; }),
        boolSetting("gi.temporal_filter",
                "blend the indirect light with earlier frames reprojected into this view, "
                "history rejected by depth and normal",
                [](Settings& s) -> bool& { return s.temporal.filter; }),
        floatSetting("gi.temporal_blend", "weight of the new frame in the temporal filter", 0.01f,
                1.0f, [](Settings& s) -> float& { return s.temporal.blend; }),
        floatSetting("gi.temporal_blend_moving",
                "least weight of the new frame in the temporal filter while the geometry moves",
                0.01f, 1.0f, [](Settings& s) -> float& { return s.temporal.blendMoving; }),
        boolSetting("gi.temporal_clamp",
                "clip the temporal filter's history to the new frame's 3x3 mean +- one deviation",
                [](Settings& s) -> bool& { return s.temporal.clamp; }),
        intSetting("reference.spp", "reference renderer: paths per pixel", 1, 65536,
                [](Settings& s) -> int& { return s.reference.spp; }),
        intSetting("reference.bounces", "reference renderer: indirect bounces (1 = one bounce)",
                1, 16, [](Settings& s) -> int& { return s.reference.bounces; }),
        intSetting("reference.seed", "reference renderer: random seed", 0, 2147483647,
                [](Settings& s) -> int& { return s.reference.seed; }),
        choiceSetting("reference.pixel",
                "reference renderer: paths over the pixel's square or through its centre",
                {"area", "centre"}, [](Settings& s) -> int& { return s.reference.pixel; }),
        intSetting("reference.threads", "reference renderer: threads (0 = all cores)", 0, 1024,
                [](Settings& s) -> int& { return s.reference.threads; }),
        floatSetting("view.frame_budget_ms",
                "viewer: frame time held while the camera moves by lowering the render "
                "resolution; a still view refines to full resolution (0 = off)",
                0.0f, 10000.0f, [](Settings& s) -> float& { return s.frameBudgetMs; }),
        hidden(boolSetting("view.screenshot_ui",
                "view --frames N --screenshot includes the overlay",
                [](Settings& s) -> bool& { return s.screenshotUi; })),
    };
    return specs;
}

bool applySetting(Settings& settings, const std::string& assignment, std::string& error) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        error = "--set expects key=value, got '" + assignment + "'";
        return false;
    }
    const std::string key = assignment.substr(0, eq);
    const std::string value = assignment.substr(eq + 1);
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.key != key) continue;
        std::string why;
        if (!spec.set(settings, value, why)) {
            error = "--set " + key + ": " + why;
            return false;
        }
        return true;
    }
    error = "--set: unknown key '" + key + "' (voxatlas render --help lists them)";
    return false;
}

std::string settingsHelp() {
    const Settings defaults;
    std::ostringstream out;
    for (const SettingSpec& spec : settingSpecs()) {
        if (spec.hidden) continue;
        // Key and default in columns; the help text as long as it is.
        char columns[64];
        std::snprintf(columns, sizeof columns, "  %-22s %-8s ", spec.key.c_str(),
                spec.get(defaults).c_str());
        out << columns << spec.help << '\n';
    }
    return out.str();
}

} // namespace gi
