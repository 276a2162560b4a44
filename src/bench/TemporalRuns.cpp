#include "bench/TemporalRuns.h"

#include "render/FrameRenderer.h"
#include "scene/Animation.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <memory>

namespace gi::bench {
namespace {

// A renderer in `mode` at `settings`, or nullptr with the reason.
std::unique_ptr<render::FrameRenderer> makeRenderer(const scene::Scene& scene,
        render::GiMode mode, const Settings& settings, gl::ShaderLibrary& shaders,
        std::string& error) {
    auto renderer = std::make_unique<render::FrameRenderer>();
    if (!renderer->init(scene, settings, shaders, error) || !renderer->setMode(mode, error)) {
        return nullptr;
    }
    renderer->setPose(scene);
    return renderer;
}

CoveredFrame renderFrame(render::FrameRenderer& renderer, const scene::CameraView& camera,
        glm::ivec2 size, render::OutputComponent output) {
    gl::GpuProfiler profiler;
    renderer.render(camera, size, output, profiler);
    return {renderer.readback(), renderer.readbackCoverage()};
}

scene::CameraView cameraAt(const TemporalPath& path, int frame) {
    scene::CameraView camera = path.start;
    const glm::vec3 offset = path.step * float(frame);
    camera.eye += offset;
    camera.view = camera.view * glm::translate(glm::mat4(1.0f), -offset);
    return camera;
}

// The technique's light came from resources placed anew this frame (a cascade's snap).
bool resampled(const render::FrameRenderer& renderer) {
    return renderer.technique() && renderer.technique()->outputs().resampled;
}

// What the moving-cube run rendered: see measureGhosting.
struct GhostFrames {
    CoveredFrame freshStart, lastMoving;
    std::vector<CoveredFrame> held, fresh;   // fresh[k]: the fresh render matching held[k-1]
};

void scoreGhost(const GhostSetup& setup, const GhostFrames& frames, GhostMeasurement& result) {
    const CoveredFrame& freshEnd = frames.fresh.back();
    const auto blocks = [&](const CoveredFrame& frame) { return blockMean(frame, setup.block); };
    const CoveredFrame freshEndBlocks = blocks(freshEnd);
    const int floorRow = int(setup.floorRows * float(freshEndBlocks.image.height));
    result.floorLight = meanLuminanceOfRows(freshEndBlocks, floorRow);
    const std::vector<bool> region = changedPixels(blocks(frames.freshStart), freshEndBlocks,
            setup.regionThreshold * result.floorLight);
    int inRegion = 0, coveredBlocks = 0;
    for (std::size_t p = 0; p < region.size(); ++p) {
        inRegion += region[p] ? 1 : 0;
        coveredBlocks += freshEndBlocks.coverage[p] > 0.5f ? 1 : 0;
    }
    result.regionFraction = coveredBlocks > 0 ? double(inRegion) / coveredBlocks : 0.0;
    result.trailMoving = trailBrightness(blocks(frames.lastMoving), blocks(frames.fresh.front()),
            region, result.floorLight);
    for (std::size_t k = 0; k < frames.held.size(); ++k) {
        result.trail.push_back(trailBrightness(blocks(frames.held[k]), blocks(frames.fresh[k + 1]),
                region, result.floorLight));
        result.strip.push_back(frames.held[k].image);
    }
    result.strip.push_back(freshEnd.image);
    result.strip.push_back(differenceImage(frames.held.back().image, freshEnd.image, 10.0f));
}

} // namespace

std::vector<int> stripFrames(int frames) {
    if (frames <= 1) return {0};
    const int last = frames - 1;
    std::vector<int> picks{0, last / 3, (2 * last) / 3, last};
    picks.erase(std::unique(picks.begin(), picks.end()), picks.end());
    return picks;
}

bool renderDirectPath(const TemporalPath& path, const Settings& settings,
        gl::ShaderLibrary& shaders, std::vector<CoveredFrame>& frames, std::string& error) {
    auto renderer = makeRenderer(*path.scene, render::GiMode::Direct, settings, shaders, error);
    if (!renderer) return false;
    frames.clear();
    for (int i = 0; i < path.frames; ++i) {
        frames.push_back(renderFrame(*renderer, cameraAt(path, i), path.size,
                render::OutputComponent::Direct));
    }
    return true;
}

bool measureFlicker(const TemporalPath& path, const TemporalConfiguration& configuration,
        const std::vector<CoveredFrame>& direct, gl::ShaderLibrary& shaders,
        FlickerMeasurement& result, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    auto renderer = makeRenderer(*path.scene, configuration.mode, configuration.settings,
            shaders, error);
    if (!renderer) return false;
    result = {};
    result.path = path.name;
    result.label = configuration.label;
    const std::vector<int> strip = stripFrames(path.frames);
    for (int i = 0; i < path.warmupFrames; ++i) {
        renderFrame(*renderer, path.start, path.size, render::OutputComponent::Indirect);
    }
    CoveredFrame previous;
    double sum = 0.0;
    for (int i = 0; i < path.frames; ++i) {
        CoveredFrame frame = renderFrame(*renderer, cameraAt(path, i), path.size,
                render::OutputComponent::Indirect);
        if (i > 0) {
            result.perFrame.push_back(relativeFrameChange(previous, frame));
            sum += result.perFrame.back();
            result.cascadeMoved.push_back(resampled(*renderer));
        }
        if (std::find(strip.begin(), strip.end(), i) != strip.end()) {
            result.strip.push_back(frame.image);
        }
        previous = std::move(frame);
    }
    result.indirectChange = result.perFrame.empty() ? 0.0 : sum / double(result.perFrame.size());
    result.directChange = meanFrameChange(direct);
    result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

bool measureGhosting(const GhostSetup& setup, const TemporalConfiguration& configuration,
        gl::ShaderLibrary& shaders, GhostMeasurement& result, std::string& error) {
    scene::Scene& scene = *setup.scene;
    const auto indirect = render::OutputComponent::Indirect;
    Settings freshSettings = configuration.settings;
    freshSettings.temporal.filter = false;
    const float endTime = setup.startTime + setup.stepSeconds * float(setup.movingFrames);
    result = {};
    result.label = configuration.label;

    // The start pose, converged without history: one end of the motion region.
    scene::poseScene(scene, setup.startTime);
    CoveredFrame freshStart;
    {
        auto fresh = makeRenderer(scene, configuration.mode, freshSettings, shaders, error);
        if (!fresh) return false;
        for (int i = 0; i <= setup.settleFrames; ++i) {
            freshStart = renderFrame(*fresh, setup.camera, setup.size, indirect);
        }
    }

    auto renderer = makeRenderer(scene, configuration.mode, configuration.settings, shaders, error);
    if (!renderer) return false;
    for (int i = 0; i <= setup.settleFrames; ++i) {
        renderFrame(*renderer, setup.camera, setup.size, indirect);
    }
    CoveredFrame lastMoving;
    for (int i = 1; i <= setup.movingFrames; ++i) {
        scene::poseScene(scene, setup.startTime + setup.stepSeconds * float(i));
        renderer->setPose(scene);
        lastMoving = renderFrame(*renderer, setup.camera, setup.size, indirect);
    }
    std::vector<CoveredFrame> held;
    for (int k = 1; k <= setup.holdFrames; ++k) {
        held.push_back(renderFrame(*renderer, setup.camera, setup.size, indirect));
    }

    // The same pose from a renderer that never saw another one, frame for frame: its first
    // frame matches the last moving frame, its (k+1)-th the k-th held frame.
    scene::poseScene(scene, endTime);
    auto fresh = makeRenderer(scene, configuration.mode, freshSettings, shaders, error);
    if (!fresh) return false;
    std::vector<CoveredFrame> freshFrames;
    for (int k = 0; k <= setup.holdFrames; ++k) {
        freshFrames.push_back(renderFrame(*fresh, setup.camera, setup.size, indirect));
    }

    scoreGhost(setup, {freshStart, std::move(lastMoving), std::move(held), std::move(freshFrames)},
            result);
    return true;
}

} // namespace gi::bench
