// The options only `voxatlas view` takes, for CommandLine.cpp's option table: the frames of a
// scripted run, the keys pressed and files dropped at given frames, the screenshot, and how
// many frames the --move motion lasts. Each applies one value to the Config or says why not.
#pragma once

#include "app/CommandLine.h"

#include <string>

namespace gi::app {

[[nodiscard]] bool applyFrames(Config& config, const std::string& flag, const std::string& value,
        std::string& error);
[[nodiscard]] bool applyScreenshot(Config& config, const std::string& flag,
        const std::string& value, std::string& error);
[[nodiscard]] bool applyKeys(Config& config, const std::string& flag, const std::string& value,
        std::string& error);
[[nodiscard]] bool applyDrop(Config& config, const std::string& flag, const std::string& value,
        std::string& error);
[[nodiscard]] bool applyMoveFrames(Config& config, const std::string& flag,
        const std::string& value, std::string& error);

} // namespace gi::app
