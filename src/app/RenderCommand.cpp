#include "app/RenderCommand.h"

#include "app/SceneSetup.h"
#include "app/TimingsReport.h"
#include "gl/GpuProfiler.h"
#include "gl/Limits.h"
#include "gl/ShaderLibrary.h"
#include "platform/GlContext.h"
#include "render/FrameRenderer.h"
#include "reference/ProgressBar.h"
#include "reference/ReferenceCache.h"
#include "core/ImageIO.h"
#include "core/ToneMap.h"
#include "scene/Animation.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace gi::app {
namespace {

int fail(int status, const std::string& message) {
    std::fprintf(stderr, "voxatlas render: %s\n", message.c_str());
    return status;
}

// What --out holds: `image` at the exposure and through the curve of --exposure and
// --tonemap (core/ToneMap.h). The defaults leave it linear at exposure 1, untouched.
core::Image displayImage(const Config& config, const core::Image& image,
        const std::vector<float>& coverage) {
    const core::ToneMapping& mapping = config.toneMapping;
    if (!mapping.autoExposure && mapping.ev == 0.0f && mapping.curve == core::ToneCurve::None) {
        return image;
    }
    const float exposure = core::exposureFor(mapping, image, coverage);
    if (mapping.autoExposure) {
        std::fprintf(stderr, "voxatlas render: auto exposure %+.2f EV\n", std::log2(exposure));
    }
    return core::applyToneMapping(image, exposure, mapping.curve);
}

// Writes --out (tone mapped), --hdr (linear radiance) and --timings (the report is only built
// when asked for); on failure removes what it had written, so a failed render leaves no
// partial output.
bool writeOutputs(const Config& config, const core::Image& image,
        const std::vector<float>& coverage, const std::function<TimingsReport()>& timings,
        std::string& error) {
    std::vector<std::string> written;
    auto cleanUp = [&] {
        for (const std::string& path : written) std::filesystem::remove(path);
        return false;
    };
    if (!core::writePng(config.outPath, displayImage(config, image, coverage), error)) {
        return cleanUp();
    }
    written.push_back(config.outPath);
    if (!config.hdrPath.empty()) {
        if (!core::writeHdr(config.hdrPath, image, error)) return cleanUp();
        written.push_back(config.hdrPath);
    }
    if (!config.timingsPath.empty() && !writeTimingsJson(config.timingsPath, timings(), error)) {
        return cleanUp();
    }
    return true;
}

// The ground-truth path tracer: no GL context, results cached on disk by content.
int runReference(const Config& config, const scene::Scene& scene, const scene::CameraView& camera,
        int width, int height) {
    if (!render::outputAvailable(config.output, render::GiMode::Reference)) {
        return fail(2, std::string("--output ") + render::outputComponentName(config.output) +
                " is a GPU technique's debug view; the reference renders final, direct or indirect");
    }
    const reference::ReferenceCache cache(reference::ReferenceCache::defaultDirectory());
    reference::CachedRenderStatus status;
    std::string error;
    reference::ProgressBar bar("reference " + std::to_string(width) + "x" + std::to_string(height) +
            ", " + std::to_string(config.settings.reference.spp) + " spp");
    const reference::ReferenceResult result = reference::renderReferenceCached(scene, camera, width,
            height, config.settings.pathTracer(), cache, status, error, bar.callback());
    bar.finish();
    if (result.final.empty()) return fail(1, error);
    if (!status.storeError.empty()) std::fprintf(stderr, "voxatlas render: %s\n", status.storeError.c_str());
    const core::Image& image = config.output == render::OutputComponent::Direct ? result.direct
                                 : config.output == render::OutputComponent::Indirect ? result.indirect
                                                                                      : result.final;
    const auto timings = [&] {
        const double ms = result.seconds * 1e3;
        return TimingsReport{config.scenePath, render::giModeName(render::GiMode::Reference),
                "cpu", "embree", "wall-clock", width, height, 1,
                {{"reference/path_trace", ms, ms, ms, 1}}, {}};
    };
    if (!writeOutputs(config, image, {}, timings, error)) return fail(1, error);
    std::fprintf(stderr,
            "voxatlas render: wrote %s (%dx%d, reference, %d spp, %d bounce(s), %s, noise %.2f%% "
            "final / %.2f%% indirect)\n",
            config.outPath.c_str(), width, height, result.spp, result.bounces,
            status.hit ? "from cache" : ("rendered in " + std::to_string(result.seconds) + " s").c_str(),
            100.0 * result.noise.final, 100.0 * result.noise.indirect);
    return 0;
}

// Warm-up and timed frames. --move: each frame sees the camera one step further along the
// same view direction; --animate: and the scene's animations that much later.
void renderFrames(const Config& config, scene::Scene& scene, scene::CameraView camera,
        glm::ivec2 size, render::FrameRenderer& renderer, gl::GpuProfiler& profiler) {
    float animationTime = config.animationTime;
    auto step = [&] {
        camera.eye += config.cameraMove;
        camera.view = camera.view * glm::translate(glm::mat4(1.0f), -config.cameraMove);
        if (config.animationStep > 0.0f) {
            animationTime += config.animationStep;
            scene::poseScene(scene, animationTime);
            renderer.setPose(scene);
        }
    };
    for (int frame = 0; frame < config.settings.warmupFrames; ++frame) {
        renderer.render(camera, size, config.output, profiler);
        step();
    }
    profiler.clearSamples();
    for (int frame = 0; frame < config.settings.frames; ++frame) {
        renderer.render(camera, size, config.output, profiler);
        profiler.collect();
        if (frame + 1 < config.settings.frames) step();
    }
    profiler.flush();
}

} // namespace

int runRender(const Config& config) {
    std::string error;
    for (const std::string* path : {&config.outPath, &config.hdrPath, &config.timingsPath}) {
        if (!path->empty() && !core::checkWritable(*path, error)) return fail(2, error);
    }

    scene::Scene scene;
    if (!loadScene(config, scene, error)) return fail(2, error);

    const int width = config.width > 0 ? config.width : 512;
    const int height = config.height > 0 ? config.height : 512;
    scene::CameraView camera;
    if (!selectCamera(config, scene, float(width) / float(height), camera, error)) return fail(2, error);
    if (config.mode == render::GiMode::Reference) return runReference(config, scene, camera, width, height);
    if (!render::FrameRenderer::shadowMapsFit(scene.lights, config.settings.shadow, error) ||
            !render::lineSpaceFits(scene, config.settings, error)) {
        return fail(2, error);
    }

    std::string notice;
    auto context = platform::createHeadlessContext(config.gl, !config.glExplicit, error, notice);
    if (!context) return fail(1, "no OpenGL 4.5 context: " + error);
    if (!notice.empty()) std::fprintf(stderr, "voxatlas render: %s\n", notice.c_str());
    if (config.settings.glDebug) platform::installDebugMessageLog();

    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    if (!renderer.init(scene, config.settings, shaders, error)) return fail(1, error);
    if (!renderer.setMode(config.mode, error)) return fail(2, error);

    gl::GpuProfiler profiler;
    renderFrames(config, scene, camera, {width, height}, renderer, profiler);
    if (const gi::GiTechnique* technique = renderer.technique(); technique &&
            !technique->failure().empty()) {
        return fail(2, technique->failure());
    }
    if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
        return fail(1, gl::glErrorName(glError) + " while rendering" +
                (glError == GL_OUT_OF_MEMORY ? ": the driver ran out of memory (lower the "
                                               "resolutions with --set)" : ""));
    }

    const core::Image image = renderer.readback();
    if (!core::allFinite(image)) return fail(1, "the rendered image has non-finite pixels");

    const auto timings = [&] {
        return TimingsReport{config.scenePath, render::giModeName(config.mode),
                std::string(context->provider()), context->description(),
                profiler.mode() == gl::TimingMode::Finish ? "finish" : "queries", width, height,
                config.settings.frames, profiler.timings(), renderer.memory(),
                renderer.shadowReport(), renderer.vplReport()};
    };
    // Auto exposure meters the pixels that show geometry, not the empty background.
    const std::vector<float> coverage = config.toneMapping.autoExposure
                                                ? renderer.readbackCoverage()
                                                : std::vector<float>{};
    if (!writeOutputs(config, image, coverage, timings, error)) return fail(1, error);
    std::fprintf(stderr, "voxatlas render: wrote %s (%dx%d, %s, %s)\n", config.outPath.c_str(),
            width, height, render::giModeName(config.mode), std::string(context->provider()).c_str());
    return 0;
}

} // namespace gi::app
