#include "app/SettingHotkeys.h"

#include "gl/Shared.h"

#include <algorithm>

namespace gi::app {

const std::vector<SettingHotkey>& settingHotkeys() {
    static const std::vector<SettingHotkey> hotkeys = {
        {"L", "cascade level shown by voxel debug views", "voxel.debug_level",
                [](Settings& s, float) {
                    s.voxel.debugLevel = (s.voxel.debugLevel + 1) % s.voxel.levels;
                }},
        {"Y", "pixel class whose VPLs the vpl-subset view highlights", "vpl.debug_subset",
                [](Settings& s, float) {
                    s.vpl.debugSubset = (s.vpl.debugSubset + 1) % (VPL_TILE * VPL_TILE);
                }},
        {"F1", "voxel resolution / 2", "voxel.resolution",
                [](Settings& s, float) { s.voxel.resolution = std::max(8, s.voxel.resolution / 2); }},
        {"F2", "voxel resolution x 2", "voxel.resolution",
                [](Settings& s, float) {
                    s.voxel.resolution = std::min(256, s.voxel.resolution * 2);
                }},
        {"F3", "one cascade level less", "voxel.cascades",
                [](Settings& s, float) {
                    s.voxel.levels = std::max(1, s.voxel.levels - 1);
                    s.voxel.debugLevel = std::min(s.voxel.debugLevel, s.voxel.levels - 1);
                }},
        {"F4", "one cascade level more", "voxel.cascades",
                [](Settings& s, float) { s.voxel.levels = std::min(8, s.voxel.levels + 1); }},
        {"F5", "cone-trace resolution 1, 1/2, 1/4, 1/8", "voxel.trace_scale",
                [](Settings& s, float) {
                    s.voxel.traceScale =
                            s.voxel.traceScale <= 0.125f ? 1.0f : s.voxel.traceScale * 0.5f;
                }},
        {"F6", "voxelization multiplier 1, 2, 4, 8, 16", "voxel.multiplier",
                [](Settings& s, float) {
                    s.voxel.multiplier = s.voxel.multiplier >= 16 ? 1 : s.voxel.multiplier * 2;
                }},
        {"F7", "injection resolution: the plan's (v on the fixed plan), 2v, 4v, 8v",
                "voxel.inject_resolution",
                [](Settings& s, float) {
                    const int v = s.voxel.resolution;
                    const int current = s.voxel.injectResolution > 0 ? s.voxel.injectResolution : v;
                    s.voxel.injectResolution = current >= 8 * v ? 0 : current * 2;
                }},
        {"F8", "max cone distance / 2 (from the coarsest level's edge)", "voxel.max_distance",
                [](Settings& s, float coarsestReach) {
                    const float start =
                            s.voxel.maxDistance > 0.0f ? s.voxel.maxDistance : coarsestReach;
                    s.voxel.maxDistance = start * 0.5f;
                }},
        {"F9", "max cone distance x 2 (0 = the coarsest level's edge)", "voxel.max_distance",
                [](Settings& s, float coarsestReach) {
                    s.voxel.maxDistance = s.voxel.maxDistance * 2.0f >= coarsestReach
                                                  ? 0.0f
                                                  : s.voxel.maxDistance * 2.0f;
                }},
        {"F10", "depth-aware / bilinear upsampling", "voxel.upsample_depth",
                [](Settings& s, float) { s.voxel.depthUpsample = !s.voxel.depthUpsample; }},
        {"F11", "injection: flux per area / the thesis' fragment mean",
                "voxel.inject_fragment_mean",
                [](Settings& s, float) {
                    s.voxel.injectFragmentMean = !s.voxel.injectFragmentMean;
                }},
        {"K", "shadows of direct light: shadow maps / BVH rays / line-space rays / voxel cone", "shadow.method",
                [](Settings& s, float) {
                    s.shadow.method = (s.shadow.method + 1) % SHADOW_METHOD_COUNT;
                }},
        {"J", "shadow rays per area light / 2", "shadow.rays",
                [](Settings& s, float) { s.shadow.rays = std::max(1, s.shadow.rays / 2); }},
        {"U", "shadow rays per area light x 2", "shadow.rays",
                [](Settings& s, float) { s.shadow.rays = std::min(1024, s.shadow.rays * 2); }},
        {"N", "line space: children per axis N = 4 .. 10 (rebuilds it)", "linespace.n",
                [](Settings& s, float) { s.lineSpace.n = s.lineSpace.n >= 10 ? 4 : s.lineSpace.n + 1; }},
        {"M", "line space: depth 2, 3, 4 (rebuilds it)", "linespace.depth",
                [](Settings& s, float) {
                    s.lineSpace.depth = s.lineSpace.depth >= 4 ? 2 : s.lineSpace.depth + 1;
                }},
    };
    return hotkeys;
}

} // namespace gi::app
