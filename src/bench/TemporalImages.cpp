#include "bench/TemporalImages.h"

#include "core/ToneMap.h"

#include <algorithm>

namespace gi::bench {
namespace {

constexpr int kGap = 2;
const glm::vec3 kGapColour(0.5f);

} // namespace

float autoExposureOf(const core::Image& image) {
    const std::optional<float> average = core::logAverageLuminance(image, {});
    return average ? core::autoExposure(*average) : 1.0f;
}

core::Image composeGrid(const std::vector<GridRow>& rows) {
    int columns = 0, width = 0, height = 0;
    for (const GridRow& row : rows) {
        columns = std::max(columns, int(row.panels.size()));
        if (!row.panels.empty()) {
            width = row.panels.front().width;
            height = row.panels.front().height;
        }
    }
    if (columns == 0 || width == 0 || height == 0) return {};
    const int rowCount = int(rows.size());
    core::Image grid(columns * width + (columns - 1) * kGap,
            rowCount * height + (rowCount - 1) * kGap);
    for (int y = 0; y < grid.height; ++y) {
        for (int x = 0; x < grid.width; ++x) grid.set(x, y, kGapColour);
    }
    for (int r = 0; r < rowCount; ++r) {
        const GridRow& row = rows[std::size_t(r)];
        if (row.panels.empty()) continue;
        const float exposure =
                row.exposure > 0.0f ? row.exposure : autoExposureOf(row.panels.front());
        for (int c = 0; c < int(row.panels.size()); ++c) {
            const core::Image& panel = row.panels[std::size_t(c)];
            if (panel.width != width || panel.height != height) continue;
            const core::Image shown =
                    core::applyToneMapping(panel, exposure, core::ToneCurve::Filmic);
            const int left = c * (width + kGap), top = r * (height + kGap);
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x) grid.set(left + x, top + y, shown.at(x, y));
            }
        }
    }
    return grid;
}

} // namespace gi::bench
