#include "GpuTest.h"

#include "TestScenes.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"

#include <glad/gl.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace gi::test {

std::string GpuTest::providerName() {
    const char* env = std::getenv("VOXATLAS_GL");
    return env && *env ? env : "egl";
}

void GpuTest::SetUp() {
    const auto provider = platform::parseProvider(providerName());
    ASSERT_TRUE(provider) << "VOXATLAS_GL must be egl or osmesa, not " << providerName();
    std::string error;
    mContext = provider == platform::HeadlessProvider::Egl ? platform::createEglContext(error)
                                                           : platform::createOSMesaContext(error);
    if (!mContext) {
        const char* require = std::getenv("VOXATLAS_REQUIRE_GPU");
        if (require && std::string(require) == "1") {
            FAIL() << "no " << providerName() << " context: " << error;
        }
        GTEST_SKIP() << "no " << providerName() << " OpenGL 4.5 context: " << error;
    }
}

void GpuTest::TearDown() {
    if (mContext) EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "a GL error is pending";
    mContext.reset();
}

std::size_t bytesWithPrefix(const std::vector<gl::MemoryItem>& items, const std::string& prefix) {
    std::size_t total = 0;
    for (const gl::MemoryItem& item : items) {
        if (item.name.rfind(prefix, 0) == 0) total += item.bytes;
    }
    return total;
}

std::string sourcePath(const std::string& relative) {
    return std::string(VOXATLAS_DATA_DIR) + "/" + relative;
}

core::Image renderScene(const RenderRequest& request) {
    const std::string path = request.scenePath.empty() || request.scenePath[0] == '/'
                                     ? request.scenePath
                                     : sourcePath(request.scenePath);
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    if (!scene::loadGltf(path, scene, error, warnings)) {
        ADD_FAILURE() << error;
        return {};
    }
    addDefaults(scene);
    return renderScene(scene, request);
}

core::Image renderScene(const scene::Scene& scene, const RenderRequest& request) {
    std::string error;
    if (request.cameraIndex >= int(scene.cameras.size())) {
        ADD_FAILURE() << "the scene has no camera " << request.cameraIndex;
        return {};
    }
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    if (!renderer.init(scene, request.settings, shaders, error) ||
            !renderer.setMode(request.mode, error)) {
        ADD_FAILURE() << error;
        return {};
    }
    const scene::CameraView camera = scene::cameraFromScene(
            scene.cameras[std::size_t(request.cameraIndex)],
            float(request.width) / float(request.height), scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {request.width, request.height}, request.output, profiler);
    profiler.flush();
    return renderer.readback();
}

} // namespace gi::test

namespace gi::test {

bool pixelOnPlane(const scene::CameraView& camera, int width, int height, int x, int y,
        int axis, float value, glm::vec3& point) {
    const glm::mat4 clipToWorld = glm::inverse(camera.viewProjection());
    const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f,
            1.0f - (float(y) + 0.5f) / float(height) * 2.0f);
    const glm::vec4 nearPoint = clipToWorld * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 farPoint = clipToWorld * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 b = glm::vec3(farPoint) / farPoint.w;
    const float da = a[axis] - value, db = b[axis] - value;
    if (da * db > 0.0f) return false;
    point = a + (b - a) * (da / (da - db));
    point[axis] = value;
    return true;
}

bool pixelOnPlaneY(const scene::CameraView& camera, int width, int height, int x, int y,
        float planeY, glm::vec3& point) {
    return pixelOnPlane(camera, width, height, x, y, 1, planeY, point);
}

double sumOverMask(const core::Image& image, const std::vector<bool>& mask) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (!mask[std::size_t(y * image.width + x)]) continue;
            const glm::vec3 c = image.at(x, y);
            sum += double(c.r + c.g + c.b);
        }
    }
    return sum;
}

} // namespace gi::test
