// Atlas parameterisation on the CPU: no two triangles share a texel, charts stay `gutter`
// texels apart, every triangle gets texels, relative surface sizes are kept within the bound
// the 30-degree chart cone allows, the Cornell walls are one chart each, a scene's own valid
// TEXCOORD_1 is kept and an overlapping one replaced, and the disk cache round-trips and
// refuses damaged entries.
#include "GpuTest.h"
#include "ReferenceTestScenes.h"

#include "gi/atlas/AtlasBuilder.h"
#include "gi/atlas/AtlasCache.h"
#include "scene/GltfLoader.h"
#include "scene/SceneDefaults.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace gi::atlas {
namespace {

namespace fs = std::filesystem;

scene::Scene loadCornell() {
    scene::Scene scene;
    std::string error;
    std::vector<std::string> warnings;
    EXPECT_TRUE(scene::loadGltf(
            test::sourcePath("assets/cornell_box/cornell_box.gltf"), scene, error, warnings))
            << error;
    return scene;
}

Atlas build(const AtlasMesh& mesh, int resolution, int gutter = 2) {
    AtlasOptions options;
    options.resolution = resolution;
    options.gutter = gutter;
    Atlas atlas;
    std::string error;
    EXPECT_TRUE(buildAtlas(mesh, options, atlas, error)) << error;
    return atlas;
}

glm::dvec2 texelPosition(const Atlas& atlas, std::size_t triangle, int corner) {
    return glm::dvec2(atlas.vertices[atlas.indices[3 * triangle + std::size_t(corner)]].uv) *
            double(atlas.resolution);
}

// Does the texel square [x, x+1] x [y, y+1] meet the triangle (separating axis test)? This is
// what conservative rasterisation on the GPU writes.
bool touches(const glm::dvec2 p[3], int x, int y) {
    const glm::dvec2 lo(x, y), hi(x + 1, y + 1);
    glm::dvec2 tlo = glm::min(p[0], glm::min(p[1], p[2])),
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

// Chart id (or -1) of every texel a triangle conservatively touches; -2 where two charts meet.
std::vector<int> conservativeOwners(const Atlas& atlas, std::vector<int>& texelsPerTriangle) {
    const int r = atlas.resolution;
    std::vector<int> owner(std::size_t(r) * std::size_t(r), -1);
    texelsPerTriangle.assign(atlas.triangleCount(), 0);
    for (std::size_t t = 0; t < atlas.triangleCount(); ++t) {
        const glm::dvec2 p[3] = {
                texelPosition(atlas, t, 0), texelPosition(atlas, t, 1), texelPosition(atlas, t, 2)};
        const glm::ivec2 lo = glm::ivec2(glm::floor(glm::min(p[0], glm::min(p[1], p[2])))) - 1;
        const glm::ivec2 hi = glm::ivec2(glm::floor(glm::max(p[0], glm::max(p[1], p[2])))) + 1;
        const int chart = int(atlas.chartOf(t));
        for (int y = std::max(lo.y, 0); y <= std::min(hi.y, r - 1); ++y)
            for (int x = std::max(lo.x, 0); x <= std::min(hi.x, r - 1); ++x) {
                if (!touches(p, x, y)) continue;
                ++texelsPerTriangle[t];
                int& o = owner[std::size_t(y) * std::size_t(r) + std::size_t(x)];
                o = (o == -1 || o == chart) ? chart : -2;
            }
    }
    return owner;
}

// The packing invariants the GPU passes rely on.
void expectValidPacking(const AtlasMesh& mesh, const Atlas& atlas) {
    ASSERT_EQ(atlas.indices.size(), mesh.indices.size());
    const int r = atlas.resolution;
    // Every vertex lies inside its chart's rectangle, clear of the padding.
    const int padding = (atlas.gutter + 1) / 2;
    for (const AtlasVertex& v : atlas.vertices) {
        const AtlasChart& chart = atlas.charts[v.chart];
        const glm::dvec2 texel = glm::dvec2(v.uv) * double(r);
        EXPECT_GE(texel.x, chart.origin.x + padding);
        EXPECT_GE(texel.y, chart.origin.y + padding);
        EXPECT_LE(texel.x, chart.origin.x + chart.size.x - padding);
        EXPECT_LE(texel.y, chart.origin.y + chart.size.y - padding);
        EXPECT_LE(chart.origin.x + chart.size.x, r);
        EXPECT_LE(chart.origin.y + chart.size.y, r);
    }
    // No two triangles own one texel centre (the GPU's exact pass writes each texel once).
    std::vector<int> centreOwner(std::size_t(r) * std::size_t(r), -1);
    int doubleClaims = 0;
    for (std::size_t t = 0; t < atlas.triangleCount(); ++t) {
        forEachTexelCentre(texelPosition(atlas, t, 0), texelPosition(atlas, t, 1),
                texelPosition(atlas, t, 2), [&](int x, int y) {
                    ASSERT_TRUE(x >= 0 && y >= 0 && x < r && y < r);
                    int& o = centreOwner[std::size_t(y) * std::size_t(r) + std::size_t(x)];
                    if (o >= 0) ++doubleClaims;
                    o = int(t);
                });
    }
    EXPECT_EQ(doubleClaims, 0) << "texel centres inside two triangles";
    // Conservative footprints: every triangle touches a texel, no texel is touched by two
    // charts, and between two charts lie at least `gutter` untouched texels.
    std::vector<int> perTriangle;
    const std::vector<int> owner = conservativeOwners(atlas, perTriangle);
    for (std::size_t t = 0; t < perTriangle.size(); ++t) {
        EXPECT_GT(perTriangle[t], 0) << "triangle " << t << " gets no texel";
    }
    int shared = 0, tooClose = 0;
    for (int y = 0; y < r; ++y)
        for (int x = 0; x < r; ++x) {
            const int o = owner[std::size_t(y) * std::size_t(r) + std::size_t(x)];
            if (o == -2) ++shared;
            if (o < 0) continue;
            for (int dy = -atlas.gutter; dy <= atlas.gutter; ++dy)
                for (int dx = -atlas.gutter; dx <= atlas.gutter; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= r || ny >= r) continue;
                    const int other = owner[std::size_t(ny) * std::size_t(r) + std::size_t(nx)];
                    if (other >= 0 && other != o) ++tooClose;
                }
        }
    EXPECT_EQ(shared, 0) << "texels touched by two charts";
    EXPECT_EQ(tooClose, 0) << "texel pairs of two charts closer than the gutter";
}

// Atlas area of each chart over its world area, in units of the packing density: the
// projection onto the seed plane shrinks a triangle at most by cos(30 deg).
void expectAreaRatiosKept(const AtlasMesh& mesh, const Atlas& atlas) {
    std::vector<double> atlasArea(atlas.charts.size(), 0.0);
    for (std::size_t t = 0; t < atlas.triangleCount(); ++t) {
        const glm::dvec2 a = texelPosition(atlas, t, 0), b = texelPosition(atlas, t, 1),
                         c = texelPosition(atlas, t, 2);
        atlasArea[atlas.chartOf(t)] +=
                0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    const double texelArea = atlas.texelSize * atlas.texelSize;
    double worldTotal = 0.0;
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        worldTotal += atlas.charts[c].area;
        // In texels^2: float UVs round a corner by up to 2^-24 of the atlas, so allow 1e-4
        // relative plus 1e-3 texel^2 for charts of slivers.
        const double world = atlas.charts[c].area / texelArea;
        EXPECT_GE(atlasArea[c], std::cos(glm::radians(30.0)) * world * (1.0 - 1e-4) - 1e-3)
                << "chart " << c;
        EXPECT_LE(atlasArea[c], world * (1.0 + 1e-4) + 1e-3) << "chart " << c;
    }
    double meshArea = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) meshArea += triangleArea(mesh, t);
    EXPECT_NEAR(worldTotal, meshArea, 1e-9 * meshArea);
    EXPECT_NEAR(atlas.surfaceArea, meshArea, 1e-9 * meshArea);
}

TEST(AtlasBuilder, CornellWallsAreOneChartEach) {
    const scene::Scene scene = loadCornell();
    const AtlasMesh mesh = flattenScene(scene);
    const Atlas atlas = build(mesh, 256);
    ASSERT_EQ(mesh.triangleCount(), 30u);
    EXPECT_FALSE(atlas.fromTexcoord1);
    // Instances 0-4 are floor, ceiling, back, left (red) and right (green) wall: two
    // triangles each, triangles 2i and 2i+1. The blocks' 10 faces are one chart each.
    for (int wall = 0; wall < 5; ++wall) {
        const std::uint32_t chart = atlas.chartOf(std::size_t(2 * wall));
        EXPECT_EQ(atlas.chartOf(std::size_t(2 * wall + 1)), chart) << "wall " << wall;
        EXPECT_EQ(atlas.charts[chart].triangles, 2u) << "wall " << wall;
    }
    EXPECT_EQ(atlas.charts.size(), 15u);
    expectValidPacking(mesh, atlas);
    expectAreaRatiosKept(mesh, atlas);
    // The packing uses the atlas well: the walls fill more than 40% of its texels.
    EXPECT_GT(atlas.surfaceArea / (atlas.texelSize * atlas.texelSize), 0.4 * 256.0 * 256.0);
}

// A UV sphere: curved, so charts are bands limited by the 30-degree cone; 2 texel gutters at
// a small resolution and a wide gutter at a large one.
AtlasMesh sphere(int rings, int segments) {
    scene::Scene scene;
    scene::Primitive p;
    for (int i = 0; i <= rings; ++i) {
        const float theta = glm::pi<float>() * float(i) / float(rings);
        for (int j = 0; j <= segments; ++j) {
            const float phi = 2.0f * glm::pi<float>() * float(j) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                    std::sin(theta) * std::sin(phi));
            p.positions.push_back(n);
            p.normals.push_back(n);
        }
    }
    const auto index = [&](int i, int j) { return std::uint32_t(i * (segments + 1) + j); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            p.indices.insert(p.indices.end(), {index(i, j), index(i, j + 1), index(i + 1, j)});
            p.indices.insert(
                    p.indices.end(), {index(i, j + 1), index(i + 1, j + 1), index(i + 1, j)});
        }
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    scene.primitives.push_back(p);
    scene.instances.push_back({});
    return flattenScene(scene);
}

TEST(AtlasBuilder, CurvedMeshPacksWithoutOverlapAtEveryGutter) {
    const AtlasMesh mesh = sphere(24, 48);
    for (const auto& [resolution, gutter] : {std::pair{128, 2}, std::pair{512, 5}}) {
        const Atlas atlas = build(mesh, resolution, gutter);
        EXPECT_GT(atlas.charts.size(), 6u) << "a sphere needs several 30-degree charts";
        expectValidPacking(mesh, atlas);
        expectAreaRatiosKept(mesh, atlas);
    }
}

// A ramp winding twice around a vertical axis with a gentle slope: every normal is within 30
// degrees of vertical, but the turns lie above each other, so one chart would fold onto itself.
TEST(AtlasBuilder, SelfOverlappingSurfaceIsSplit) {
    scene::Scene scene;
    scene::Primitive p;
    const int steps = 96;
    for (int i = 0; i <= steps; ++i) {
        const float angle = 4.0f * glm::pi<float>() * float(i) / float(steps);
        const float height = 0.3f * float(i) / float(steps);
        for (const float radius : {0.5f, 1.0f}) {
            p.positions.emplace_back(radius * std::cos(angle), height, radius * std::sin(angle));
            p.normals.emplace_back(0.0f, 1.0f, 0.0f);
        }
    }
    for (int i = 0; i < steps; ++i) {
        const auto a = std::uint32_t(2 * i);
        p.indices.insert(p.indices.end(), {a, a + 2, a + 1, a + 1, a + 2, a + 3});
    }
    for (const glm::vec3& v : p.positions) p.localBounds.extend(v);
    scene.primitives.push_back(p);
    scene.instances.push_back({});
    const AtlasMesh mesh = flattenScene(scene);
    const Atlas atlas = build(mesh, 256);
    EXPECT_GE(atlas.charts.size(), 2u);
    expectValidPacking(mesh, atlas);
}

// Two unit quads; `overlap` places both at the same TEXCOORD_1.
AtlasMesh quadsWithTexcoord1(bool overlap) {
    scene::Scene scene;
    const int white = test::addMaterial(scene, glm::vec3(0.5f));
    test::addQuad(scene,
            {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 0, -1), glm::vec3(0, 0, -1)},
            white);
    test::addQuad(scene,
            {glm::vec3(0, 0, -1), glm::vec3(1, 0, -1), glm::vec3(1, 1, -1), glm::vec3(0, 1, -1)},
            white);
    scene.primitives[0].texcoords1 = {{0.1f, 0.1f}, {0.4f, 0.1f}, {0.4f, 0.4f}, {0.1f, 0.4f}};
    scene.primitives[1].texcoords1 = overlap
            ? scene.primitives[0].texcoords1
            : std::vector<glm::vec2>{{0.5f, 0.5f}, {0.8f, 0.5f}, {0.8f, 0.8f}, {0.5f, 0.8f}};
    return flattenScene(scene);
}

TEST(AtlasBuilder, KeepsAValidTexcoord1AndReplacesAnOverlappingOne) {
    const AtlasMesh valid = quadsWithTexcoord1(false);
    ASSERT_TRUE(valid.hasTexcoord1);
    std::string why;
    EXPECT_TRUE(texcoord1IsAtlas(valid, 64, why)) << why;
    const Atlas kept = build(valid, 64);
    EXPECT_TRUE(kept.fromTexcoord1);
    EXPECT_EQ(kept.charts.size(), 2u);
    for (const AtlasVertex& v : kept.vertices) EXPECT_EQ(v.uv, valid.texcoords1[v.source]);
    // 0.3 x 0.3 of a 64^2 atlas for 1 m^2: 19.2 texels per metre.
    EXPECT_NEAR(kept.texelSize, 1.0 / 19.2, 0.05 / 19.2);

    const AtlasMesh overlapping = quadsWithTexcoord1(true);
    EXPECT_FALSE(texcoord1IsAtlas(overlapping, 64, why));
    EXPECT_NE(why.find("overlaps"), std::string::npos) << why;
    const Atlas rebuilt = build(overlapping, 64);
    EXPECT_FALSE(rebuilt.fromTexcoord1);
    expectValidPacking(overlapping, rebuilt);
}

TEST(AtlasBuilder, TooManyChartsForTheResolutionIsAClearError) {
    const AtlasMesh mesh = sphere(24, 48);
    AtlasOptions options;
    options.resolution = 16;
    Atlas atlas;
    std::string error;
    EXPECT_FALSE(buildAtlas(mesh, options, atlas, error));
    EXPECT_NE(error.find("atlas.resolution 16"), std::string::npos) << error;
}

// A 1.4 km sliver of 0.5 m^2, and a 1 m triangle 6e-39 m wide (found by the fuzzer): their
// area alone allows thousands, or 1e21, texels per metre, which once rasterised the first for
// hours and overflowed the second. Their longest edge bounds the density instead.
TEST(AtlasBuilder, LongSliversPackQuickly) {
    const std::vector<std::vector<glm::vec3>> slivers = {
            {{0, 0, 0}, {1000, 1000, 0}, {1000, 1000.001f, 0}},
            {{0, 0, 0}, {1, 0, 0}, {0, 0, 5.7856e-39f}},
    };
    for (const std::vector<glm::vec3>& corners : slivers) {
        AtlasMesh mesh;
        mesh.positions = corners;
        mesh.normals.assign(3, glm::vec3(0, 0, 1));
        mesh.indices = {0, 1, 2};
        const Atlas atlas = build(mesh, 256);
        expectValidPacking(mesh, atlas);
    }
}

TEST(AtlasBuilder, EmptySceneIsAClearError) {
    Atlas atlas;
    std::string error;
    EXPECT_FALSE(buildAtlas(AtlasMesh{}, AtlasOptions{}, atlas, error));
    EXPECT_FALSE(error.empty());
}

fs::path freshCacheDir(const std::string& name) {
    const fs::path dir = fs::path(VOXATLAS_TEST_OUTPUT_DIR) / "atlas-cache" / name;
    fs::remove_all(dir);
    return dir;
}

bool sameAtlas(const Atlas& a, const Atlas& b) {
    if (a.resolution != b.resolution || a.gutter != b.gutter || a.texelSize != b.texelSize ||
            a.surfaceArea != b.surfaceArea || a.indices != b.indices ||
            a.vertices.size() != b.vertices.size() || a.charts.size() != b.charts.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        if (a.vertices[i].source != b.vertices[i].source ||
                a.vertices[i].chart != b.vertices[i].chart ||
                a.vertices[i].uv != b.vertices[i].uv) {
            return false;
        }
    }
    for (std::size_t i = 0; i < a.charts.size(); ++i) {
        if (a.charts[i].origin != b.charts[i].origin || a.charts[i].size != b.charts[i].size ||
                a.charts[i].area != b.charts[i].area ||
                a.charts[i].triangles != b.charts[i].triangles) {
            return false;
        }
    }
    return true;
}

TEST(AtlasCache, RoundTripsAndRebuildsDamagedEntries) {
    const AtlasMesh mesh = flattenScene(loadCornell());
    const AtlasCache cache(freshCacheDir("round-trip"));
    AtlasOptions options;
    options.resolution = 256;
    Atlas built, loaded;
    AtlasBuildInfo info;
    std::string error;
    ASSERT_TRUE(loadOrBuildAtlas(mesh, options, &cache, built, info, error)) << error;
    EXPECT_FALSE(info.cacheHit);
    EXPECT_TRUE(info.cacheError.empty()) << info.cacheError;
    ASSERT_TRUE(fs::exists(info.cacheFile));
    ASSERT_TRUE(loadOrBuildAtlas(mesh, options, &cache, loaded, info, error)) << error;
    EXPECT_TRUE(info.cacheHit);
    EXPECT_TRUE(sameAtlas(built, loaded));

    // Every option and the geometry are part of the key.
    const std::string key = atlasCacheKey(mesh, options);
    AtlasOptions other = options;
    other.gutter = 3;
    EXPECT_NE(atlasCacheKey(mesh, other), key);
    other = options;
    other.resolution = 512;
    EXPECT_NE(atlasCacheKey(mesh, other), key);
    AtlasMesh moved = mesh;
    moved.positions[0].x += 1e-3f;
    EXPECT_NE(atlasCacheKey(moved, options), key);
    EXPECT_FALSE(cache.load(key, AtlasMesh{}, loaded))
            << "an entry that does not fit the mesh is refused";

    // A flipped byte anywhere, or a truncated file, is refused and then rebuilt.
    const fs::path file = cache.entryPath(key);
    std::vector<char> bytes;
    {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    for (const std::size_t offset : {std::size_t(3), bytes.size() / 2, bytes.size() - 1}) {
        std::vector<char> damaged = bytes;
        damaged[offset] = char(damaged[offset] ^ 0x20);
        std::ofstream(file, std::ios::binary | std::ios::trunc)
                .write(damaged.data(), std::streamsize(damaged.size()));
        EXPECT_FALSE(cache.load(key, mesh, loaded)) << "byte " << offset;
    }
    std::ofstream(file, std::ios::binary | std::ios::trunc)
            .write(bytes.data(), std::streamsize(bytes.size() / 2));
    EXPECT_FALSE(cache.load(key, mesh, loaded));
    ASSERT_TRUE(loadOrBuildAtlas(mesh, options, &cache, loaded, info, error)) << error;
    EXPECT_FALSE(info.cacheHit);
    EXPECT_TRUE(sameAtlas(built, loaded));
    EXPECT_TRUE(cache.load(key, mesh, loaded)) << "the rebuild replaced the damaged entry";
}

TEST(AtlasCache, DefaultDirectoryFollowsTheEnvironment) {
    const char* saved = std::getenv("VOXATLAS_CACHE_DIR");
    const std::string previous = saved ? saved : "";
    setenv("VOXATLAS_CACHE_DIR", "/tmp/va-cache", 1);
    EXPECT_EQ(AtlasCache::defaultDirectory(), fs::path("/tmp/va-cache/atlas"));
    if (saved)
        setenv("VOXATLAS_CACHE_DIR", previous.c_str(), 1);
    else
        unsetenv("VOXATLAS_CACHE_DIR");
    if (!saved) {
        const char* xdg = std::getenv("XDG_CACHE_HOME");
        const char* home = std::getenv("HOME");
        if (xdg && *xdg)
            EXPECT_EQ(AtlasCache::defaultDirectory(), fs::path(xdg) / "voxatlas" / "atlas");
        else if (home && *home) {
            EXPECT_EQ(AtlasCache::defaultDirectory(),
                    fs::path(home) / ".cache" / "voxatlas" / "atlas");
        }
    }
}

} // namespace
} // namespace gi::atlas
