// voxatlas: diffuse global illumination by voxel cone tracing and by a texture-atlas gather,
// measured against a ground-truth renderer. This file only dispatches to the commands.
#include "app/BenchCommand.h"
#include "app/CommandLine.h"
#include "app/InfoCommand.h"
#include "app/RenderCommand.h"
#include "app/Usage.h"
#include "app/Viewer.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    using namespace gi::app;
    try {
        std::string error;
        const auto config = parseCommandLine(argc, argv, error);
        if (!config) {
            std::fprintf(stderr, "voxatlas: %s\n", error.c_str());
            return 2;
        }
        if (!config->plan.note.empty()) {
            std::fprintf(stderr, "voxatlas: %s\n", config->plan.note.c_str());
        }
        switch (config->command) {
        case Command::Help: std::fputs(usage(config->helpFor).c_str(), stdout); return 0;
        case Command::Render: return runRender(*config);
        case Command::Info: return runInfo(*config);
        case Command::View: return runViewer(*config);
        case Command::Bench: return runBench(*config);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "voxatlas: internal error: %s\n", e.what());
        return 1;
    }
    return 1;
}
