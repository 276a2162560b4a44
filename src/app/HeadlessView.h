// `voxatlas view` without a display: the frame the viewer would have shown, rendered through
// `voxatlas render` to --screenshot (or voxatlas-view.png), with the viewer's size and its
// exposure and tone curve (CommandLine gives view auto exposure and the filmic curve).
#pragma once

#include "app/CommandLine.h"

#include <glm/glm.hpp>

#include <string>

namespace gi::app {

// `windowError`: why no window opened ("no display: ..."), repeated on stderr.
[[nodiscard]] int runHeadlessView(const Config& config, glm::ivec2 size,
        const std::string& windowError);

} // namespace gi::app
