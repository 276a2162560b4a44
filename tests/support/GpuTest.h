// Base fixture for headless GPU tests: one GL 4.5 core context per test from the provider
// named by VOXATLAS_GL (egl or osmesa; ctest runs the suite once per provider). Without a
// context the test is skipped with the reason, unless VOXATLAS_REQUIRE_GPU=1 (CI), which
// makes it a failure. TearDown asserts that no GL error is pending.
#pragma once

#include "platform/GlContext.h"
#include "scene/CameraView.h"
#include "render/FrameRenderer.h"
#include "core/Image.h"
#include "core/Settings.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace gi::test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // The provider under test ("egl" or "osmesa").
    static std::string providerName();

    std::unique_ptr<platform::GlContext> mContext;
};

// The default settings with render.plan=fixed: the thesis' allocation (voxel.cascades levels
// around the camera, atlas.resolution texels) that tests of those settings, their probes and
// goldens are written against; the default plan sizes both from the scene.
inline Settings thesisAllocation() {
    Settings settings;
    settings.plan = PLAN_FIXED;
    return settings;
}

struct RenderRequest {
    std::string scenePath;            // relative paths are taken from the source tree
    int width = 64, height = 64;
    int cameraIndex = 0;
    render::OutputComponent output = render::OutputComponent::Final;
    Settings settings;
    render::GiMode mode = render::GiMode::Direct;
};

// Loads, renders and reads back one frame with the current context. Fails the test (and
// returns an empty image) on any error.
[[nodiscard]] core::Image renderScene(const RenderRequest& request);

// Renders a scene built in code (lights and cameras as given; no defaults are added).
[[nodiscard]] core::Image renderScene(const scene::Scene& scene, const RenderRequest& request);

// Bytes of the memory-report rows (FrameRenderer::memory()) whose names start with `prefix`.
[[nodiscard]] std::size_t bytesWithPrefix(const std::vector<gl::MemoryItem>& items,
        const std::string& prefix);

// World-space point seen through the centre of pixel (x, y) on the plane where coordinate
// `axis` (0 = x, 1 = y, 2 = z) equals `value`, or false if the pixel's ray misses it.
// Images run top to bottom.
[[nodiscard]] bool pixelOnPlane(const scene::CameraView& camera, int width, int height, int x,
        int y, int axis, float value, glm::vec3& point);
// pixelOnPlane on the plane y = planeY.
[[nodiscard]] bool pixelOnPlaneY(const scene::CameraView& camera, int width, int height, int x,
        int y, float planeY, glm::vec3& point);

// The sum of r + g + b over the pixels whose entry in `mask` (row-major, the image's size)
// is true.
[[nodiscard]] double sumOverMask(const core::Image& image, const std::vector<bool>& mask);

// Absolute path of a file in the source tree (assets/..., tests/...).
[[nodiscard]] std::string sourcePath(const std::string& relative);

} // namespace gi::test
