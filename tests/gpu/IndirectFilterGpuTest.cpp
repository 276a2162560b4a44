// The edge-aware filter of voxel GI's traced light (gi/voxel/IndirectFilterPass.h) on a
// synthetic trace: two planes meeting along a vertical edge at one depth, like a block's top
// and its front seen from above, the light of one 1 and of the other 0. Weighted by view
// depth alone, the filter carried each side's light over the edge, whose texels lie at
// nearly the centre's depth; weighted also by the distance from the centre's plane, each
// side keeps its own.
#include "GpuTest.h"

#include "gi/voxel/IndirectFilterPass.h"
#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "gl/Shared.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace gi::test {
namespace {

constexpr glm::ivec2 kSize{32, 16};
constexpr int kEdge = 16;   // columns 0..15 are the lit plane, 16..31 the dark one

class IndirectFilterGpuTest : public GpuTest {};

// 1/depth is affine in screen space over a plane: the sides meet 2 m away between columns 15
// and 16 (a ridge: the depth is least at the edge), 1/depth falling by 0.4 % a texel on the
// lit side and 1.2 % on the dark one away from it. A texel two columns from the edge has the
// depth of the texel across it, so the depth weight (e^-1 at 2 %) cannot tell them apart.
float depthAt(int x) {
    const float offset = float(x) + 0.5f - float(kEdge);
    const float slope = x < kEdge ? 2.0e-3f : -6.0e-3f;
    return 1.0f / (0.5f + slope * offset);
}

// The filtered light of column x (every row alike) at `radius` texels.
std::vector<float> filteredColumns(int radius) {
    std::vector<float> texels(std::size_t(kSize.x * kSize.y) * 4);
    for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
            float* t = &texels[std::size_t(y * kSize.x + x) * 4];
            const float light = x < kEdge ? 1.0f : 0.0f;
            t[0] = t[1] = t[2] = light;
            t[3] = depthAt(x);
        }
    }
    gl::Texture source = gl::createTexture2D(GL_RGBA16F, kSize, 1, "test/trace");
    glTextureSubImage2D(source.id(), 0, 0, 0, kSize.x, kSize.y, GL_RGBA, GL_FLOAT, texels.data());
    shader::VoxelUniforms uniforms{};
    uniforms.smoothing.x = float(radius);
    gl::Buffer ubo = gl::createBuffer(sizeof uniforms, &uniforms, 0, "test/voxel_uniforms");

    gl::ShaderLibrary shaders;
    voxel::IndirectFilterPass filter;
    std::string error;
    EXPECT_TRUE(filter.init(shaders, error)) << error;
    gl::GpuProfiler profiler;
    filter.execute({source, ubo, radius}, {kSize}, profiler);
    profiler.flush();
    std::vector<float> result(texels.size());
    glGetTextureImage(filter.result().id(), 0, GL_RGBA, GL_FLOAT,
            GLsizei(result.size() * sizeof(float)), result.data());
    std::vector<float> columns(std::size_t(kSize.x));
    const int row = kSize.y / 2;
    for (int x = 0; x < kSize.x; ++x) columns[std::size_t(x)] = result[std::size_t(row * kSize.x + x) * 4];
    return columns;
}

// The default window at half resolution (2 texels) and the quality preset's (4): every
// column but the two at the edge keeps its side's light within 2 % (weighted by depth alone,
// the columns two from the edge read 0.79 and 0.18 at radius 2). The two at the edge see
// their neighbours on both planes equally close to theirs, and may take either plane.
TEST_F(IndirectFilterGpuTest, LightDoesNotCrossWhereTwoPlanesMeetAtOneDepth) {
    for (const int radius : {2, 4}) {
        const std::vector<float> columns = filteredColumns(radius);
        for (int x = 0; x < kSize.x; ++x) {
            if (x == kEdge - 1 || x == kEdge) continue;
            const float expected = x < kEdge ? 1.0f : 0.0f;
            EXPECT_NEAR(columns[std::size_t(x)], expected, 0.02f)
                    << "column " << x << ", radius " << radius;
        }
        std::printf("radius %d: columns %d..%d read %.3f %.3f | %.3f %.3f\n", radius, kEdge - 2,
                kEdge + 1, columns[kEdge - 2], columns[kEdge - 1], columns[kEdge],
                columns[kEdge + 1]);
    }
}

} // namespace
} // namespace gi::test
