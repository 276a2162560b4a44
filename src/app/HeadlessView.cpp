#include "app/HeadlessView.h"

#include "app/RenderCommand.h"

#include <cstdio>
#include <filesystem>

namespace gi::app {

int runHeadlessView(const Config& config, glm::ivec2 size, const std::string& windowError) {
    Config headless = config;
    headless.command = Command::Render;
    headless.outPath = config.screenshotPath.empty() ? "voxatlas-view.png" : config.screenshotPath;
    headless.width = size.x;
    headless.height = size.y;
    const std::string prefix = "no display: ";
    const std::string reason = windowError.rfind(prefix, 0) == 0
                                       ? windowError.substr(prefix.size())
                                       : windowError;
    std::fprintf(stderr,
            "voxatlas view: no display (%s); rendering a headless screenshot instead: %s\n",
            reason.c_str(),
            std::filesystem::absolute(headless.outPath).lexically_normal().string().c_str());
    return runRender(headless);
}

} // namespace gi::app
