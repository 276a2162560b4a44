#include "render/OutputCatalog.h"

#include <algorithm>

namespace gi::render {
namespace {

constexpr ModeMask kVoxel = modeBit(GiMode::Voxel);
constexpr ModeMask kAtlas = modeBit(GiMode::Atlas);
constexpr ModeMask kVpl = modeBit(GiMode::Vpl);

constexpr ModeEntry kModes[] = {
        {GiMode::Direct, "direct", "direct", "direct light only, no GI", true},
        {GiMode::Voxel, "voxel", "voxel GI", "voxel cone tracing over a cascade of clipmaps", true},
        {GiMode::Atlas, "atlas", "atlas GI", "texture-atlas GI gathered between atlas texels", true},
        {GiMode::Vpl, "vpl", "VPL GI",
                "virtual point lights from reflective shadow maps, voxel visibility", true},
        {GiMode::Reference, "reference", "reference",
                "the Embree path tracer (CPU ground truth, cached on disk)", false},
};

constexpr OutputEntry kOutputs[] = {
        {OutputComponent::Final, "final", DebugView::None, true, kAllModes,
                "direct + indirect light"},
        {OutputComponent::Direct, "direct", DebugView::None, true, kAllModes,
                "direct light only"},
        {OutputComponent::Indirect, "indirect", DebugView::None, true, kAllModes,
                "indirect light only"},
        {OutputComponent::VoxelAlbedo, "voxel-albedo", DebugView::VoxelAlbedo, false, kVoxel,
                "albedo of the first voxel hit, level voxel.debug_level"},
        {OutputComponent::VoxelIrradiance, "voxel-irradiance", DebugView::VoxelIrradiance, true,
                kVoxel, "voxel irradiance E, shown as E/pi, level voxel.debug_level"},
        {OutputComponent::VoxelNormal, "voxel-normal", DebugView::VoxelNormal, false, kVoxel,
                "voxel mean normal, 0.5 + 0.5 n, level voxel.debug_level"},
        {OutputComponent::AtlasDirect, "atlas-direct", DebugView::AtlasDirect, true, kAtlas,
                "outgoing direct radiance of the atlas texels"},
        {OutputComponent::AtlasNormal, "atlas-normal", DebugView::AtlasNormal, false, kAtlas,
                "atlas texel normal, 0.5 + 0.5 n"},
        {OutputComponent::AtlasPosition, "atlas-position", DebugView::AtlasPosition, false,
                kAtlas, "atlas texel world position in metres"},
        {OutputComponent::AtlasAlbedo, "atlas-albedo", DebugView::AtlasAlbedo, false, kAtlas,
                "atlas texel albedo rho"},
        {OutputComponent::AtlasIndirect, "atlas-indirect", DebugView::AtlasIndirect, true,
                kAtlas, "gathered indirect irradiance E_ind, shown as E_ind/pi"},
        {OutputComponent::AtlasCharts, "atlas-charts", DebugView::AtlasCharts, false, kAtlas,
                "a random colour per atlas chart"},
        {OutputComponent::VplPoints, "vpl-points", DebugView::VplPoints, false, kVpl,
                "the VPLs the camera sees, coloured by their flux, over grey surfaces"},
        {OutputComponent::VplSubset, "vpl-subset", DebugView::VplSubset, false, kVpl,
                "the VPLs of pixel class vpl.debug_subset of the 4x4 tiles in colour, the rest grey"},
        {OutputComponent::VplVisibility, "vpl-visibility", DebugView::VplVisibility, false, kVpl,
                "mean visibility of the VPLs facing each surface, 1 = white"},
};

} // namespace

std::span<const ModeEntry> modeCatalog() { return kModes; }
std::span<const OutputEntry> outputCatalog() { return kOutputs; }

const ModeEntry& modeEntry(GiMode mode) {
    static constexpr ModeEntry kUnknown{GiMode::Direct, "?", "?", "", false};
    const auto* entry = std::find_if(std::begin(kModes), std::end(kModes),
            [mode](const ModeEntry& e) { return e.mode == mode; });
    return entry != std::end(kModes) ? *entry : kUnknown;
}

const OutputEntry& outputEntry(OutputComponent output) {
    static constexpr OutputEntry kUnknown{OutputComponent::Final, "?", DebugView::None, true, 0,
            ""};
    const auto* entry = std::find_if(std::begin(kOutputs), std::end(kOutputs),
            [output](const OutputEntry& e) { return e.output == output; });
    return entry != std::end(kOutputs) ? *entry : kUnknown;
}

const char* giModeName(GiMode mode) { return modeEntry(mode).name; }

std::optional<GiMode> parseGiMode(std::string_view name) {
    for (const ModeEntry& entry : kModes) {
        if (name == entry.name) return entry.mode;
    }
    return std::nullopt;
}

const char* outputComponentName(OutputComponent output) { return outputEntry(output).name; }

std::optional<OutputComponent> parseOutputComponent(std::string_view name) {
    for (const OutputEntry& entry : kOutputs) {
        if (name == entry.name) return entry.output;
    }
    return std::nullopt;
}

const std::vector<OutputComponent>& allOutputComponents() {
    static const std::vector<OutputComponent> all = [] {
        std::vector<OutputComponent> outputs;
        for (const OutputEntry& entry : kOutputs) outputs.push_back(entry.output);
        return outputs;
    }();
    return all;
}

bool isDebugView(OutputComponent output) {
    return outputEntry(output).debugView != DebugView::None;
}

bool isRadiometric(OutputComponent output) { return outputEntry(output).radiometric; }

bool outputAvailable(OutputComponent output, GiMode mode) {
    return (outputEntry(output).modes & modeBit(mode)) != 0;
}

} // namespace gi::render
