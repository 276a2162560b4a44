// The GI modes and the outputs a frame can show, each named once: the command line
// (--mode, --output), `voxatlas render --help`, the viewer's mode keys and output cycle, the
// renderer's debug views and the bench's reports all read these two tables.
#pragma once

#include "gi/GiTechnique.h"

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace gi::render {

enum class GiMode { Direct, Voxel, Atlas, Vpl, Reference };

// What a frame shows: a radiance component, or a technique's debug view.
enum class OutputComponent {
    Final, Direct, Indirect, VoxelAlbedo, VoxelIrradiance, VoxelNormal,
    AtlasDirect, AtlasNormal, AtlasPosition, AtlasAlbedo, AtlasIndirect, AtlasCharts,
    VplPoints, VplSubset, VplVisibility
};

struct ModeEntry {
    GiMode mode;
    const char* name;          // --mode word, timings reports and bench rows
    const char* label;         // the viewer's overlay, key help and notices
    const char* description;   // one line of --help
    bool gpu;                  // FrameRenderer runs it (the viewer's number keys, in order)
};

// A set of GiModes, one bit per enum value.
using ModeMask = unsigned;
constexpr ModeMask modeBit(GiMode mode) { return 1u << unsigned(mode); }
constexpr ModeMask kAllModes = modeBit(GiMode::Direct) | modeBit(GiMode::Voxel) |
                               modeBit(GiMode::Atlas) | modeBit(GiMode::Vpl) |
                               modeBit(GiMode::Reference);

struct OutputEntry {
    OutputComponent output;
    const char* name;          // --output word and the viewer's output name
    DebugView debugView;       // the technique view behind it; None for a radiance component
    // In W/m^2 or W/(m^2 sr) (the components, irradiance and direct-light views), so it
    // carries the scene's pre-exposure on the GPU; false for albedo, normals, positions, charts.
    bool radiometric;
    ModeMask modes;            // the modes that can show it
    const char* description;   // one line of --help
};

// Both in the order of --help and of the viewer's cycles.
[[nodiscard]] std::span<const ModeEntry> modeCatalog();
[[nodiscard]] std::span<const OutputEntry> outputCatalog();

[[nodiscard]] const ModeEntry& modeEntry(GiMode mode);
[[nodiscard]] const OutputEntry& outputEntry(OutputComponent output);

[[nodiscard]] const char* giModeName(GiMode mode);
[[nodiscard]] std::optional<GiMode> parseGiMode(std::string_view name);
[[nodiscard]] const char* outputComponentName(OutputComponent output);
[[nodiscard]] std::optional<OutputComponent> parseOutputComponent(std::string_view name);
[[nodiscard]] const std::vector<OutputComponent>& allOutputComponents();
// True for a technique's debug view (not a radiance component).
[[nodiscard]] bool isDebugView(OutputComponent output);
[[nodiscard]] bool isRadiometric(OutputComponent output);
// False for a technique's debug view while another mode is active.
[[nodiscard]] bool outputAvailable(OutputComponent output, GiMode mode);

} // namespace gi::render
