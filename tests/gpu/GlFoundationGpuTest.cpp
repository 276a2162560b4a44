// The GL layer on a real context: version, DSA object creation, shader errors mapped to
// files, and timer queries that return plausible times.
#include "GpuTest.h"
#include "ImageCompare.h"

#include "gl/GpuProfiler.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <glad/gl.h>

#include <filesystem>
#include <fstream>

namespace gi::test {
namespace {

class GlFoundationGpuTest : public GpuTest {};

TEST_F(GlFoundationGpuTest, ContextIsGl45Core) {
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_EQ(mContext->provider(), providerName());
}

TEST_F(GlFoundationGpuTest, ShaderErrorsNameFileAndLine) {
    const std::string root = testOutputDir() + "/shader-error-" + providerName();
    std::filesystem::create_directories(root + "/pass");
    std::ofstream(root + "/pass/broken.comp")
            << "layout(local_size_x = 1) in;\nvoid main() {\n    undefinedThing = 1;\n}\n";
    gl::ShaderLibrary library(root);
    std::string error;
    const gl::ProgramRef program =
            library.build({"pass/broken", {{GL_COMPUTE_SHADER, "pass/broken.comp"}}, {"VARIANT 1"}}, error);
    EXPECT_FALSE(program);
    EXPECT_NE(error.find("shaders/pass/broken.comp:3:"), std::string::npos) << error;
    EXPECT_NE(error.find("VARIANT 1"), std::string::npos) << "active defines are listed: " << error;
    std::filesystem::remove_all(root);
}

TEST_F(GlFoundationGpuTest, ProjectShadersCompile) {
    gl::ShaderLibrary library;
    std::string error;
    EXPECT_TRUE(library.build({"render/forward", {{GL_VERTEX_SHADER, "render/forward.vert"},
                                                         {GL_FRAGMENT_SHADER, "render/forward.frag"}}, {}},
            error)) << error;
}

TEST_F(GlFoundationGpuTest, TimerQueriesMeasureWork) {
    gl::GpuProfiler profiler(gl::TimingMode::Queries);
    gl::Texture texture = gl::createTexture2D(GL_RGBA32F, {512, 512}, 1, "test/clear");
    for (int frame = 0; frame < 5; ++frame) {
        profiler.newFrame();
        gl::GpuScope scope(profiler, "test/clear");
        const float value[4] = {1.0f, 2.0f, 3.0f, 4.0f};
        glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
    }
    profiler.flush();
    const auto timings = profiler.timings();
    ASSERT_EQ(timings.size(), 1u);
    EXPECT_EQ(timings[0].name, "test/clear");
    EXPECT_EQ(timings[0].samples, 5);
    EXPECT_GT(timings[0].gpuMsMedian, 0.0);
    EXPECT_LT(timings[0].gpuMsMedian, 10000.0);
}

// llvmpipe's timestamps miss its rasterizer threads' work, so software renderers are timed
// with glFinish; the measured time must grow with the work (a 2048^2 clear against a 64^2
// one is 1000x the pixels; 4x is a bound no scheduling noise reaches).
TEST_F(GlFoundationGpuTest, FinishTimingScalesWithWork) {
    gl::GpuProfiler profiler(gl::TimingMode::Finish);
    gl::Texture small = gl::createTexture2D(GL_RGBA32F, {64, 64}, 1, "test/small");
    gl::Texture large = gl::createTexture2D(GL_RGBA32F, {2048, 2048}, 1, "test/large");
    const float value[4] = {1.0f, 2.0f, 3.0f, 4.0f};
    for (int frame = 0; frame < 5; ++frame) {
        profiler.newFrame();
        {
            gl::GpuScope scope(profiler, "test/small");
            glClearTexImage(small.id(), 0, GL_RGBA, GL_FLOAT, value);
        }
        {
            gl::GpuScope scope(profiler, "test/large");
            glClearTexImage(large.id(), 0, GL_RGBA, GL_FLOAT, value);
        }
    }
    const auto timings = profiler.timings();
    ASSERT_EQ(timings.size(), 2u);
    EXPECT_EQ(timings[0].samples, 5);
    EXPECT_GT(timings[1].gpuMsMedian, 4.0 * timings[0].gpuMsMedian);
    if (std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))).find("llvmpipe") !=
            std::string::npos) {
        EXPECT_EQ(gl::currentContextTimingMode(), gl::TimingMode::Finish);
    }
}

// A pass run several times in a frame (once per light) is one sample: the sum of its runs.
TEST_F(GlFoundationGpuTest, RepeatedScopesInOneFrameAreSummed) {
    gl::GpuProfiler profiler;
    gl::Texture texture = gl::createTexture2D(GL_RGBA32F, {256, 256}, 1, "test/clear");
    const float value[4] = {1.0f, 2.0f, 3.0f, 4.0f};
    for (int frame = 0; frame < 3; ++frame) {
        profiler.newFrame();
        for (int light = 0; light < 4; ++light) {
            gl::GpuScope scope(profiler, "test/per_light");
            glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
        }
    }
    profiler.flush();
    const auto timings = profiler.timings();
    ASSERT_EQ(timings.size(), 1u);
    EXPECT_EQ(timings[0].samples, 3);
}

TEST_F(GlFoundationGpuTest, IncompleteFramebufferIsReported) {
    gl::Framebuffer framebuffer = gl::createFramebuffer("test/empty");
    std::string error;
    EXPECT_FALSE(gl::framebufferComplete(framebuffer, "test/empty", error));
    EXPECT_NE(error.find("test/empty"), std::string::npos);
}

} // namespace
} // namespace gi::test
