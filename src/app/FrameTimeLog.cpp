#include "app/FrameTimeLog.h"

#include "core/Median.h"

#include <cstdio>
#include <utility>

namespace gi::app {

void FrameTimeLog::record(double frameMs, bool moving, glm::ivec2 renderSize) {
    mFrames.push_back({frameMs, moving, renderSize});
}

double FrameTimeLog::medianMs(bool moving) const {
    std::vector<double> ms;
    for (const Frame& frame : mFrames) {
        if (frame.moving == moving) ms.push_back(frame.ms);
    }
    return core::median(std::move(ms));
}

std::string FrameTimeLog::groupSummary(bool moving) const {
    int count = 0;
    glm::ivec2 smallest(0), largest(0);
    for (const Frame& frame : mFrames) {
        if (frame.moving != moving) continue;
        const int area = frame.size.x * frame.size.y;
        if (count == 0 || area < smallest.x * smallest.y) smallest = frame.size;
        if (count == 0 || area > largest.x * largest.y) largest = frame.size;
        ++count;
    }
    if (count == 0) return {};
    char text[160];
    std::snprintf(text, sizeof text, "%s: %d frame%s, median %.1f ms, ",
            moving ? "moving" : "still", count, count == 1 ? "" : "s", medianMs(moving));
    std::string line = text;
    auto size = [](glm::ivec2 s) { return std::to_string(s.x) + "x" + std::to_string(s.y); };
    line += size(smallest);
    if (largest != smallest) line += " to " + size(largest);
    return line;
}

std::string FrameTimeLog::summary() const {
    std::string line;
    for (bool moving : {true, false}) {
        const std::string group = groupSummary(moving);
        if (group.empty()) continue;
        line += (line.empty() ? "" : "; ") + group;
    }
    return line;
}

} // namespace gi::app
