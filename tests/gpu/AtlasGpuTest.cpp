// Texture-atlas GI on a real context: texel positions and coverage round-trip to the scene's
// geometry, the method's defining property (the indirect light does not depend on the view),
// the memory report, and golden images of the Cornell box. Emitter probes are in
// AtlasEmitterGpuTest.cpp, convergence and settings in AtlasConvergenceGpuTest.cpp.
#include "AtlasGpuTestSupport.h"
#include "ImageCompare.h"

#include <algorithm>

namespace gi::test {
namespace {


// World position of the surface point at atlas texel-space point p inside triangle t.
glm::dvec3 worldAt(
        const atlas::AtlasMesh& mesh, const atlas::Atlas& atlas, std::size_t t, glm::dvec2 p) {
    const glm::dvec2 a = texelPosition(atlas, t, 0), b = texelPosition(atlas, t, 1),
                     c = texelPosition(atlas, t, 2);
    const glm::dvec2 e1 = b - a, e2 = c - a, r = p - a;
    const double area = e1.x * e2.y - e1.y * e2.x;
    const double w1 = (r.x * e2.y - r.y * e2.x) / area, w2 = (e1.x * r.y - e1.y * r.x) / area;
    const auto corner = [&](int k) {
        return glm::dvec3(
                mesh.positions[atlas.vertices[atlas.indices[3 * t + std::size_t(k)]].source]);
    };
    return (1.0 - w1 - w2) * corner(0) + w1 * corner(1) + w2 * corner(2);
}

// Does the texel square [x, x+1] x [y, y+1] meet the triangle? (separating axes: the two
// coordinate axes and the three edge normals; touching counts.)
bool touches(const glm::dvec2 p[3], int x, int y) {
    const glm::dvec2 lo(x, y), hi(x + 1, y + 1);
    const glm::dvec2 tlo = glm::min(p[0], glm::min(p[1], p[2])),
                     thi = glm::max(p[0], glm::max(p[1], p[2]));
    if (thi.x < lo.x || tlo.x > hi.x || thi.y < lo.y || tlo.y > hi.y) return false;
    for (int e = 0; e < 3; ++e) {
        const glm::dvec2 d = p[(e + 1) % 3] - p[e];
        const glm::dvec2 n(-d.y, d.x);
        const double third = glm::dot(n, p[(e + 2) % 3] - p[e]);
        double best = third > 0.0 ? -1e300 : 1e300;
        for (const glm::dvec2 corner : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)}) {
            const double s = glm::dot(n, corner - p[e]);
            best = third > 0.0 ? std::max(best, s) : std::min(best, s);
        }
        if ((third > 0.0 && best < 0.0) || (third < 0.0 && best > 0.0)) return false;
    }
    return true;
}

// Every texel whose centre lies on a triangle holds that triangle's world position at the
// centre (within half a texel of the CPU's parameterisation; in practice float rounding),
// the texels' sample areas add up to the scene's surface area, and every texel a triangle
// touches is written (conservative draw) and has a lit value (dilation) around it.
TEST_F(AtlasGpuTest, TexelsRoundTripToWorldPositions) {
    const scene::Scene scene = loadCornellBox();
    AtlasFrame frame(scene, atlasSettings(256, 16));
    frame.render({32, 32});
    const atlas::Atlas& atlas = frame.gi().atlas();
    const atlas::AtlasMesh mesh = atlas::flattenScene(scene);
    const int r = atlas.resolution;
    const auto position = readAtlas(frame.gi().textures().position, r);
    const auto direct = readAtlas(frame.gi().textures().direct, r);
    const auto lit = frame.lit();
    const auto at = [r](int x, int y) { return std::size_t(y) * std::size_t(r) + std::size_t(x); };

    double worst = 0.0, areaSum = 0.0;
    int exact = 0, missing = 0;
    std::vector<char> centre(std::size_t(r) * std::size_t(r), 0);
    for (std::size_t t = 0; t < atlas.triangleCount(); ++t) {
        atlas::forEachTexelCentre(texelPosition(atlas, t, 0), texelPosition(atlas, t, 1),
                texelPosition(atlas, t, 2), [&](int x, int y) {
                    centre[at(x, y)] = 1;
                    const glm::vec4 p = position[at(x, y)];
                    if (p.w <= 0.0f) {
                        ++missing;
                        return;
                    }
                    const glm::dvec3 expected =
                            worldAt(mesh, atlas, t, glm::dvec2(x + 0.5, y + 0.5));
                    worst = std::max(worst, glm::length(glm::dvec3(p) - expected));
                    ++exact;
                });
    }
    for (std::size_t i = 0; i < position.size(); ++i) areaSum += position[i].w;
    ASSERT_GT(exact, 10000);
    EXPECT_EQ(missing, 0) << "texel centres on a triangle that the exact draw did not write";
    EXPECT_LE(worst, 0.5 * atlas.texelSize) << "Probe: farthest texel from its CPU position, m";
    // Each texel holds the area of the triangles' parts inside it (clipped exactly), so the
    // sum is the surface area up to float rounding (measured: a relative difference under
    // 1e-6 at 256^2).
    EXPECT_NEAR(areaSum, atlas.surfaceArea, 1e-3 * atlas.surfaceArea);

    // Conservative coverage: every texel a triangle's area meets (separating-axis test) is
    // written, and every neighbour of such a texel has a lit value (dilation).
    int unwritten = 0, unlit = 0;
    for (std::size_t t = 0; t < atlas.triangleCount(); ++t) {
        const glm::dvec2 p[3] = {
                texelPosition(atlas, t, 0), texelPosition(atlas, t, 1), texelPosition(atlas, t, 2)};
        const glm::ivec2 lo(glm::floor(glm::min(p[0], glm::min(p[1], p[2])))),
                hi(glm::floor(glm::max(p[0], glm::max(p[1], p[2]))));
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                if (!touches(p, x, y)) continue;
                if (direct[at(x, y)].a <= 0.0f) ++unwritten;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (lit[at(x + dx, y + dy)].a <= 0.0f) ++unlit;
                    }
            }
    }
    EXPECT_EQ(unwritten, 0) << "texels a triangle touches that the conservative draw missed";
    EXPECT_EQ(unlit, 0) << "texels next to a surface that bilinear lookups would read as black";
}

// The thesis' goal (3.1, 5.1): the atlas holds the whole scene, so the indirect light of a
// surface point is the same whether or not the red wall is in view. The lit atlas is computed
// without the camera: bit-identical between the two views, with the senders drawn by what the
// scene's surfaces receive (atlas.importance=surfaces, the default) and by power. The pixel
// showing one floor point 12 cm from the red wall agrees between the classic view and a view
// straight down on it that does not show the wall, and the point stays redder than the mirror
// point by the green wall.
TEST_F(AtlasGpuTest, IndirectLightDoesNotDependOnTheView) {
    const scene::Scene scene = loadCornellBox();
    const glm::vec3 nearRed(0.12f, 0.0f, -0.03f), nearGreen(0.556f - 0.12f, 0.0f, -0.03f);
    const scene::Camera withoutWall =
            lookAtCamera(nearRed + glm::vec3(0.0f, 0.3f, 0.0f), nearRed, 20.0f);
    const glm::ivec2 size(64, 64);
    AtlasFrame a(scene, atlasSettings(256, 1024)), b(scene, atlasSettings(256, 1024));
    a.render(size, render::OutputComponent::Indirect);
    b.render(size, render::OutputComponent::Indirect, 1, withoutWall);
    EXPECT_TRUE(a.lit() == b.lit()) << "the lit atlas depends on the camera";
    {
        // The senders drawn by power alone: no view either.
        Settings power = atlasSettings(256, 1024);
        power.atlas.importance = ATLAS_IMPORTANCE_POWER;
        AtlasFrame c(scene, power), d(scene, power);
        c.render(size, render::OutputComponent::Indirect);
        d.render(size, render::OutputComponent::Indirect, 1, withoutWall);
        EXPECT_TRUE(c.lit() == d.lit())
                << "atlas.importance=power: the lit atlas depends on the camera";
        EXPECT_FALSE(c.lit() == a.lit()) << "the draws by power and by the surfaces agree";
    }

    auto pixelOf = [&](const scene::Camera& camera, const glm::vec3& point, glm::ivec2& pixel) {
        const scene::CameraView view = scene::cameraFromScene(camera, 1.0f, scene.bounds);
        const glm::vec4 clip = view.viewProjection() * glm::vec4(point, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        pixel = glm::ivec2(glm::floor((glm::vec2(ndc.x, -ndc.y) * 0.5f + 0.5f) * glm::vec2(size)));
        return glm::all(glm::greaterThanEqual(pixel, glm::ivec2(0))) &&
                glm::all(glm::lessThan(pixel, size));
    };
    glm::ivec2 pa, pb, pg;
    ASSERT_TRUE(pixelOf(scene.cameras[0], nearRed, pa));
    ASSERT_TRUE(pixelOf(withoutWall, nearRed, pb));
    ASSERT_TRUE(pixelOf(scene.cameras[0], nearGreen, pg));
    // The red wall is the plane x = 0: every pixel of the second view sees the floor at x > 0.
    const scene::CameraView viewB = scene::cameraFromScene(withoutWall, 1.0f, scene.bounds);
    glm::vec3 leftEdge;
    ASSERT_TRUE(pixelOnPlaneY(viewB, size.x, size.y, 0, size.y / 2, 0.0f, leftEdge));
    ASSERT_GT(std::min(leftEdge.x, 0.24f - leftEdge.x), 0.02f)
            << "the second view must not show the red wall";
    const core::Image imageA = a.image(), imageB = b.image();
    const glm::vec3 ia = imageA.at(pa.x, pa.y), ib = imageB.at(pb.x, pb.y);
    ASSERT_GT(ia.r, 0.0f);
    // The two pixels' footprints on the floor differ by millimetres: E changes by well under
    // 5% over that distance.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ib[c], ia[c], 0.05f * ia[c]) << "channel " << c;
    // Colour bleeding, on the mean of the 3x3 pixels around each point (each texel's estimate
    // has its own noise, ~5% at 256 samples): red/green near the red wall exceeds red/green at
    // the mirror point near the green wall. Measured on llvmpipe with 1024 samples: 1.049-1.058
    // over three rotations, and 1.06 after 8192 samples. The path tracer's 1.34 is larger
    // because the short block hides much of the box from the point near the green wall, and
    // the atlas without visibility does not see it; the bound leaves room for the noise.
    auto meanAround = [&](glm::ivec2 p) {
        glm::vec3 sum(0.0f);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) sum += imageA.at(p.x + dx, p.y + dy);
        return sum / 9.0f;
    };
    const glm::vec3 red = meanAround(pa), green = meanAround(pg);
    EXPECT_GT(red.r / red.g, 1.03f * green.r / green.g)
            << "near red " << red.r << "," << red.g << " near green " << green.r << ","
            << green.g;
}

TEST_F(AtlasGpuTest, MemoryReportMatchesTheLayers) {
    const scene::Scene scene = loadCornellBox();
    AtlasFrame frame(scene, atlasSettings(256, 64));
    frame.render({32, 32});
    // The report reads what was allocated (gl/MemoryRegistry.h).
    std::size_t layers = 0;
    for (const char* layer : {"atlas/direct", "atlas/normal", "atlas/position", "atlas/albedo",
                 "atlas/sums", "atlas/lit"}) {
        layers += bytesWithPrefix(frame.renderer().memory(), layer);
    }
    // direct, normal, albedo, lit RGBA16F (8 B) + position, sums RGBA32F (16 B) per texel.
    EXPECT_EQ(layers, std::size_t(256) * 256 * (4 * 8 + 2 * 16));
}

struct AtlasGolden {
    const char* name;
    render::OutputComponent output;
};

class AtlasGoldenGpuTest : public GpuTest, public ::testing::WithParamInterface<AtlasGolden> {};

// Cornell box, camera 0, 128x128, atlas 256^2, 64 samples, one frame.
TEST_P(AtlasGoldenGpuTest, CornellView) {
    const scene::Scene scene = loadCornellBox();
    AtlasFrame frame(scene, atlasSettings(256, 64));
    frame.render({128, 128}, GetParam().output);
    const core::Image image = frame.image();
    ASSERT_TRUE(core::allFinite(image));
    // The atlas passes have no order-dependent atomics: the defaults (6/255, 0.2%, 0.5/255)
    // hold between runs and between the EGL and OSMesa contexts of one Mesa build.
    const std::string failure =
            compareWithReference(image, std::string("frame/") + GetParam().name);
    EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(Views, AtlasGoldenGpuTest,
        ::testing::Values(AtlasGolden{"cornell_atlas_final", render::OutputComponent::Final},
                AtlasGolden{"cornell_atlas_indirect", render::OutputComponent::Indirect},
                AtlasGolden{"cornell_atlas_charts", render::OutputComponent::AtlasCharts}),
        [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace gi::test
