// The frame times of a scripted viewer run (--frames N), split into frames rendered while the
// camera moved (at the frame budget's reduced resolution) and still ones (full resolution),
// summarised in one line at the end of the run: what the frame-budget tests and the figures
// in docs/usage.md read.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gi::app {

class FrameTimeLog {
public:
    void record(double frameMs, bool moving, glm::ivec2 renderSize);

    // "moving: 20 frames, median 98.2 ms, 412x232 to 640x360; still: 15 frames, median
    // 350.1 ms, 1280x720" (a group without frames is left out).
    [[nodiscard]] std::string summary() const;
    [[nodiscard]] double medianMs(bool moving) const;

private:
    struct Frame {
        double ms;
        bool moving;
        glm::ivec2 size;
    };
    [[nodiscard]] std::string groupSummary(bool moving) const;

    std::vector<Frame> mFrames;
};

} // namespace gi::app
