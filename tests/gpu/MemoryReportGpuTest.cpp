// The memory report (FrameRenderer::memory(), read from gl/MemoryRegistry.h) is what the GL
// holds: after a frame in each mode and debug view, its total equals the sizes the GL gives for
// every texture and buffer allocated since the renderer was made, each recorded size equals the
// GL's, and destroying the renderer leaves nothing recorded.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/MemoryRegistry.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "gl/Shared.h"
#include "render/FrameRenderer.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

namespace gi::test {
namespace {

// Bytes of a texture's storage from what the GL reports for each level: the sum of its
// components' bits (independent of gl::bytesPerTexel) times its texels.
std::size_t glTextureBytes(GLuint id) {
    GLint levels = 0;
    glGetTextureParameteriv(id, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    std::size_t bytes = 0;
    for (GLint level = 0; level < levels; ++level) {
        auto get = [&](GLenum parameter) {
            GLint value = 0;
            glGetTextureLevelParameteriv(id, level, parameter, &value);
            return std::size_t(value);
        };
        std::size_t bits = 0;
        for (const GLenum component : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
                     GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE,
                     GL_TEXTURE_STENCIL_SIZE}) {
            bits += get(component);
        }
        bytes += get(GL_TEXTURE_WIDTH) * get(GL_TEXTURE_HEIGHT) * get(GL_TEXTURE_DEPTH) * bits / 8;
    }
    return bytes;
}

std::size_t glBufferBytes(GLuint id) {
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(id, GL_BUFFER_SIZE, &size);
    return std::size_t(size);
}

bool isIn(const gl::Allocation& a, const std::vector<gl::Allocation>& list) {
    return std::any_of(list.begin(), list.end(),
            [&](const gl::Allocation& b) { return a.kind == b.kind && a.id == b.id; });
}

// Checks every allocation made since `before` against the GL, and that `report` sums to them.
void expectReportIsWhatGlHolds(const std::vector<gl::MemoryItem>& report,
        const std::vector<gl::Allocation>& before, const std::string& what) {
    std::size_t held = 0;
    for (const gl::Allocation& a : gl::liveAllocations()) {
        if (isIn(a, before)) continue;
        const bool texture = a.kind == gl::StorageKind::Texture;
        ASSERT_TRUE(texture ? glIsTexture(a.id) : glIsBuffer(a.id)) << what << ": " << a.label;
        const std::size_t bytes = texture ? glTextureBytes(a.id) : glBufferBytes(a.id);
        EXPECT_EQ(a.bytes, bytes) << what << ": " << a.label;
        held += bytes;
    }
    EXPECT_EQ(gl::totalBytes(report), held) << what << ": every allocation is in the report";
}

bool hasRow(const std::vector<gl::MemoryItem>& report, const std::string& name) {
    return std::any_of(report.begin(), report.end(),
            [&](const gl::MemoryItem& item) { return item.name == name && item.bytes > 0; });
}

struct ModeCase {
    render::GiMode mode;
    std::optional<render::OutputComponent> debugView;
    int atlasVisibility = ATLAS_VISIBILITY_NONE;
};

class MemoryReportGpuTest : public GpuTest {};

TEST_F(MemoryReportGpuTest, ReportIsWhatTheGlHoldsInEveryMode) {
    const scene::Scene box = loadCornellBox();
    const glm::ivec2 size(24, 24);
    const scene::CameraView camera = scene::cameraFromScene(box.cameras[0], 1.0f, box.bounds);
    const std::vector<gl::Allocation> before = gl::liveAllocations();
    const ModeCase cases[] = {
            {render::GiMode::Direct, std::nullopt},
            {render::GiMode::Voxel, render::OutputComponent::VoxelAlbedo},
            {render::GiMode::Atlas, render::OutputComponent::AtlasCharts},
            {render::GiMode::Atlas, std::nullopt, ATLAS_VISIBILITY_VOXEL},
            {render::GiMode::Vpl, render::OutputComponent::VplPoints}};
    for (const ModeCase& c : cases) {
        const std::string what = std::string(render::giModeName(c.mode)) +
                (c.atlasVisibility == ATLAS_VISIBILITY_VOXEL ? " with voxel visibility" : "");
        {
            Settings settings = thesisAllocation();
            settings.atlas.resolution = 128;
            settings.atlas.samples = 64;
            settings.atlas.cache = false;
            settings.atlas.visibility = c.atlasVisibility;
            gl::ShaderLibrary shaders;
            render::FrameRenderer renderer;
            std::string error;
            ASSERT_TRUE(renderer.init(box, settings, shaders, error)) << error;
            ASSERT_TRUE(renderer.setMode(c.mode, error)) << error;
            gl::GpuProfiler profiler;
            renderer.render(camera, size, render::OutputComponent::Final, profiler);
            expectReportIsWhatGlHolds(renderer.memory(), before, what);
            if (c.debugView) {
                renderer.render(camera, size, *c.debugView, profiler);
                expectReportIsWhatGlHolds(renderer.memory(), before, what + " debug view");
            }
            profiler.flush();
            const std::vector<gl::MemoryItem> report = renderer.memory();
            EXPECT_TRUE(hasRow(report, "frame/radiance")) << what;
            EXPECT_TRUE(hasRow(report, "scene/textures")) << what << ": the white fallback";
            if (c.mode == render::GiMode::Voxel) {
                EXPECT_TRUE(hasRow(report, "voxel/inject_depth"));
                EXPECT_TRUE(hasRow(report, "voxel/debug_view"));
            }
            if (c.debugView == render::OutputComponent::AtlasCharts) {
                EXPECT_TRUE(hasRow(report, "atlas/debug_view"));
            }
            if (c.debugView == render::OutputComponent::VplPoints) {
                EXPECT_TRUE(hasRow(report, "vpl/debug_view"));
            }
            if (c.atlasVisibility == ATLAS_VISIBILITY_VOXEL) {
                EXPECT_TRUE(hasRow(report, "occupancy/voxel/albedo"));
            }
        }
        EXPECT_EQ(gl::liveAllocations().size(), before.size())
                << what << ": the renderer's textures and buffers left the record with it";
    }
}

TEST_F(MemoryReportGpuTest, RecordFollowsTheHandles) {
    const std::size_t before = gl::liveAllocations().size();
    const gl::MemoryOwner owner;
    {
        const gl::MemoryScope scope(owner);
        gl::Texture texture = gl::createTexture2D(GL_RGBA16F, {64, 32}, 2, "test/texture");
        const gl::Buffer buffer = gl::createBuffer(100, nullptr, 0, "test/buffer");
        EXPECT_EQ(gl::totalBytes(owner.report()), (64 * 32 + 32 * 16) * 8 + 100u);
        // A reallocation replaces the record of the storage it drops.
        texture = gl::createTexture2D(GL_R32UI, {16, 16}, 1, "test/texture");
        EXPECT_EQ(gl::totalBytes(owner.report()), 16 * 16 * 4 + 100u);
        EXPECT_EQ(gl::liveAllocations().size(), before + 2);
    }
    EXPECT_TRUE(owner.report().empty());
    EXPECT_EQ(gl::liveAllocations().size(), before);
}

} // namespace
} // namespace gi::test
