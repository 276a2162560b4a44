#include "bench/TemporalReport.h"

#include "bench/BenchReport.h"
#include "bench/TemporalImages.h"
#include "core/ImageIO.h"
#include "render/TemporalFilter.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace gi::bench {
namespace {

namespace fs = std::filesystem;

constexpr double kRatioTarget = 1.0;    // issue target on the Sponza walk
constexpr double kTrailTarget = 0.02;   // of the floor's indirect light, after 4 frames

std::string percent(double value, int digits = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f %%", digits, 100.0 * value);
    return text;
}

std::string number(double value, int digits = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

// The pictures leave out the unclipped filter's rows: they look like the clipped ones.
bool pictured(const std::string& label) { return label.find("no clamp") == std::string::npos; }

std::string pathImageName(const TemporalPath& path) { return "temporal_" + path.name + ".png"; }
constexpr const char* kGhostImageName = "temporal_moving_cube.png";

// Mean indirect change on the frames where the cascade snapped and on the others.
struct SnapSplit {
    int snaps = 0;
    double onSnaps = 0.0, elsewhere = 0.0;
};

SnapSplit snapSplit(const FlickerMeasurement& m) {
    SnapSplit split;
    int others = 0;
    for (std::size_t i = 0; i < m.perFrame.size() && i < m.cascadeMoved.size(); ++i) {
        if (m.cascadeMoved[i]) {
            ++split.snaps;
            split.onSnaps += m.perFrame[i];
        } else {
            ++others;
            split.elsewhere += m.perFrame[i];
        }
    }
    if (split.snaps > 0) split.onSnaps /= split.snaps;
    if (others > 0) split.elsewhere /= others;
    return split;
}

void writeDefinitions(std::ostringstream& md, const TemporalRunInfo& info) {
    md << "## What is measured\n\n"
       << "- **Frame-to-frame change** of a radiance component along a camera path: for "
          "consecutive frames a, b, Σ|Y_b − Y_a| / Σ(Y_a + Y_b)/2 over the pixels that show "
          "geometry in both (Y: Rec. 709 luminance of linear radiance), i.e. the mean absolute "
          "change relative to the mean level; the table gives its mean over the path's frame "
          "pairs. The camera moves, so even a perfect image changes (parallax, surfaces "
          "entering the view): the **direct** term (`--output direct`, shadow-mapped, the same "
          "in every mode) sets the scale, and the **ratio** indirect / direct says how much "
          "more (> 1) or less (< 1) the indirect term changes than the exactly computed direct "
          "light. Indirect light is smoother than direct light, so a stable method stays below "
          "1 (target on the Sponza walk: ≤ " << number(kRatioTarget, 1) << ").\n"
       << "- **Filter**: `gi.temporal_filter=1` (the default; the rows without it set 0) with "
          "`gi.temporal_blend=" << number(info.blend, 2)
       << "` and history clipping (`gi.temporal_clamp=1`; *no clamp*: 0), in the renderer "
          "after the technique (render/TemporalFilter.h). On a frame where the voxel cascade "
          "snapped the light steps where nothing changed, so the clipping pauses while the "
          "exponential average fades the step in (until the history holds under 5 % of the "
          "light from before it: " << render::TemporalFilter::fadeFrames(info.blend)
       << " frames at blend " << number(info.blend, 2) << "). On frames where animated "
          "geometry moved the new frame weighs at least `gi.temporal_blend_moving="
       << number(info.blendMoving, 2) << "`: the light around a moving object changes a "
          "little every frame, inside the clip, and an average of weight "
       << number(info.blend, 2) << " lags it by " << number(1.0 / info.blend - 1.0, 1)
       << " frames.\n"
       << "- Every frame of a path is rendered in order by one renderer per configuration, as "
          "in the viewer: voxel caches, the atlas' progressive sums and the temporal filter's "
          "history persist.\n"
       << "- **Cascade snaps** (voxel mode): frames where the camera-centred cascade's centre "
          "moved (it snaps to the coarsest voxel); the change on those frames against the "
          "others shows whether snapping pops.\n"
       << "- **Trail** of the animated Cornell box's cube: the cube slides (the file's "
          "animation), then stops. Each held frame k is compared with a *fresh* render of the "
          "same pose: a new renderer that never saw another pose, given as many frames at this "
          "pose (so progressive methods are compared at equal sample counts). Both are averaged "
          "over 4×4-pixel blocks first, so per-pixel sample noise does not count as a trail. "
          "Trail(k) = mean |Y_history − Y_fresh| over the **motion region** (blocks where the "
          "fresh renders of "
          "the start and end poses differ by more than 5 % of the floor's light: where a trail "
          "can be), divided by the floor's mean indirect luminance (fresh render, the covered "
          "blocks of the lowest fifth of the image, which sees only floor). Target: ≤ "
       << percent(kTrailTarget, 0) << " after 4 frames.\n\n";
}

void writePath(std::ostringstream& md, const TemporalPathResult& result) {
    const TemporalPath& path = result.path;
    md << "## " << path.name << "\n\n"
       << path.description << " (`" << path.scenePath << "`, " << path.frames << " frames at "
       << path.size.x << "×" << path.size.y << ", after " << path.warmupFrames
       << " frames at the start).";
    if (path.name == "sponza_walk") md << " Target: ratio ≤ " << number(kRatioTarget, 1) << ".";
    md << "\n\n"
       << "| configuration | indirect change | direct change | ratio | cascade snaps | change on "
          "snap frames | on the others | s |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const FlickerMeasurement& m : result.measurements) {
        const double ratio = m.directChange > 0.0 ? m.indirectChange / m.directChange : 0.0;
        const SnapSplit split = snapSplit(m);
        const bool voxel = m.label.rfind("voxel", 0) == 0;
        md << "| " << m.label << " | " << percent(m.indirectChange) << " | "
           << percent(m.directChange) << " | " << number(ratio) << " | "
           << (voxel ? std::to_string(split.snaps) : "–") << " | "
           << (voxel && split.snaps > 0 ? percent(split.onSnaps) : "–") << " | "
           << (voxel ? percent(split.elsewhere) : "–") << " | " << number(m.seconds, 1) << " |\n";
    }
    md << "\n![" << path.name << "](images/" << pathImageName(path) << ")\n\n"
       << "Rows: the direct term, then the indirect term of each configuration in the table's "
          "order (without the *no clamp* rows); columns: frames";
    for (int frame : stripFrames(path.frames)) md << " " << frame;
    md << ".\n\n";
}

void writeGhost(std::ostringstream& md, const TemporalGhostResult& ghost) {
    const GhostSetup& s = ghost.setup;
    md << "## Moving cube (ghosting)\n\n"
       << "`" << s.scenePath << "` at " << s.size.x << "×" << s.size.y << ": settled "
       << s.settleFrames << " frames at t = " << number(s.startTime, 2) << " s, then "
       << s.movingFrames << " frames of " << number(s.stepSeconds, 3)
       << " s of animation each, then held still for " << s.holdFrames << " frames.\n\n"
       << "| configuration | floor light (W/m²/sr) | motion region | trail, last moving frame |";
    for (int k = 1; k <= s.holdFrames; ++k) md << " trail after " << k << " |";
    md << "\n|---|---:|---:|---:|";
    for (int k = 1; k <= s.holdFrames; ++k) md << "---:|";
    md << "\n";
    for (const GhostMeasurement& m : ghost.measurements) {
        md << "| " << m.label << " | " << number(m.floorLight, 4) << " | "
           << percent(m.regionFraction, 1) << " | " << percent(m.trailMoving) << " |";
        for (double t : m.trail) md << " " << percent(t) << " |";
        md << "\n";
    }
    md << "\n![moving cube](images/" << kGhostImageName << ")\n\n"
       << "Rows: the configurations in the table's order (without the *no clamp* rows); "
          "columns: held frames 1–"
       << s.holdFrames << ", the fresh render, and |history − fresh| × 10 of the last held "
          "frame.\n\n";
}

bool writeImages(const fs::path& directory, const std::vector<TemporalPathResult>& paths,
        const TemporalGhostResult& ghost, std::string& error) {
    const fs::path images = directory / "images";
    std::error_code ec;
    fs::create_directories(images, ec);
    for (const TemporalPathResult& result : paths) {
        std::vector<GridRow> rows{{result.directStrip, 0.0f}};
        for (const FlickerMeasurement& m : result.measurements) {
            if (pictured(m.label)) rows.push_back({m.strip, 0.0f});
        }
        const std::string file = (images / pathImageName(result.path)).string();
        if (!core::writePng(file, composeGrid(rows), error)) {
            return false;
        }
    }
    if (ghost.measurements.empty()) return true;
    std::vector<GridRow> rows;
    for (const GhostMeasurement& m : ghost.measurements) {
        if (!pictured(m.label)) continue;
        // One exposure for the row, the fresh render's, so the difference panel is comparable.
        const float exposure =
                m.strip.size() >= 2 ? autoExposureOf(m.strip[m.strip.size() - 2]) : 0.0f;
        rows.push_back({m.strip, exposure});
    }
    return core::writePng((images / kGhostImageName).string(), composeGrid(rows), error);
}

} // namespace

std::string temporalMarkdown(const std::vector<TemporalPathResult>& paths,
        const TemporalGhostResult& ghost, const TemporalRunInfo& info) {
    std::ostringstream md;
    md << "# Temporal stability: flicker along camera paths and trails behind moving objects\n\n"
       << "Written by `" << info.command << "` (" << info.form << " form) on " << info.date
       << ", " << info.glRenderer << ", in " << number(info.seconds / 60.0, 1) << " min.\n\n";
    for (const std::string& note : info.notes) md << "> " << note << "\n\n";
    writeDefinitions(md, info);
    for (const TemporalPathResult& result : paths) writePath(md, result);
    if (!ghost.measurements.empty()) writeGhost(md, ghost);
    return md.str();
}

bool writeTemporalReport(const std::string& directory, const std::vector<TemporalPathResult>& paths,
        const TemporalGhostResult& ghost, const TemporalRunInfo& info, std::string& error) {
    const fs::path dir(directory);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!writeImages(dir, paths, ghost, error)) return false;
    return writeFileAtomically(dir / "results-temporal.md", temporalMarkdown(paths, ghost, info),
            error);
}

} // namespace gi::bench
