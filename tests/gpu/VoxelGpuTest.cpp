// Voxel cone tracing on a real context, stage by stage, on the thesis' allocation (three
// camera-centred levels, render.plan=fixed) unless a test says otherwise. Expected values come from the scene's geometry and
// radiometry (piglit-style probes), plus golden images of the Cornell box's debug views.
#include "GpuTest.h"
#include "ImageCompare.h"
#include "TestScenes.h"
#include "VoxelFrame.h"

#include "gi/voxel/VoxelizationManager.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <glad/gl.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

namespace gi::test {
namespace {

std::vector<glm::vec4> readVolume(const gl::Texture& texture, const voxel::CascadeVolume& volume) {
    const int v = volume.resolution();
    std::vector<glm::vec4> texels(volume.texelCount());
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)),
            texels.data());
    (void)v;
    return texels;
}

std::size_t texelIndex(const voxel::CascadeVolume& volume, glm::ivec3 voxel, int level) {
    const auto v = std::size_t(volume.resolution());
    return (std::size_t(level) * v + std::size_t(voxel.z)) * v * v + std::size_t(voxel.y) * v +
           std::size_t(voxel.x);
}

// Points spread over every triangle of the scene, `spacing` apart or closer.
std::vector<glm::vec3> surfaceSamples(const scene::Scene& scene, float spacing) {
    std::vector<glm::vec3> points;
    for (const scene::Instance& instance : scene.instances) {
        const scene::Primitive& p = scene.primitives[std::size_t(instance.primitive)];
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const glm::vec3 a = glm::vec3(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t]], 1.0f));
            const glm::vec3 b = glm::vec3(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t + 1]], 1.0f));
            const glm::vec3 c = glm::vec3(instance.worldFromLocal * glm::vec4(p.positions[p.indices[t + 2]], 1.0f));
            const int n = int(std::ceil(std::max(glm::length(b - a), glm::length(c - a)) / spacing)) + 1;
            for (int i = 0; i <= n; ++i) {
                for (int j = 0; i + j <= n; ++j) {
                    points.push_back(a + (b - a) * (float(i) / float(n)) + (c - a) * (float(j) / float(n)));
                }
            }
        }
    }
    return points;
}

class VoxelGpuTest : public GpuTest {};

struct SurfaceCoverage {
    std::size_t expected = 0;   // voxels the scene's surfaces pass through (away from faces)
    std::size_t covered = 0;    // of those, the occupied ones
    int stray = 0;              // voxels occupied farther than one voxel from any surface
    double share() const { return expected ? double(covered) / double(expected) : 0.0; }
};

// Which voxels of `level` (every level when -1) the scene's surfaces pass through, and how
// many of them the frame occupied.
SurfaceCoverage surfaceCoverage(const scene::Scene& scene, const VoxelFrame& frame, int onlyLevel) {
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);

    // Sample points strictly inside voxels: a surface lying exactly on a voxel face may be
    // stored in either neighbour, so points within 1% of a voxel face are not counted.
    std::set<std::tuple<int, int, int, int>> expected, nearSurface;
    for (const glm::vec3& p : surfaceSamples(scene, volume.voxelSize(0) / 8.0f)) {
        const auto level = volume.finestLevelContaining(p);
        if (!level) continue;
        const float size = volume.voxelSize(*level);
        const glm::vec3 local = (p - volume.origin(*level)) / size;
        const glm::ivec3 voxel = volume.voxelOf(p, *level);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    nearSurface.insert({*level, voxel.x + dx, voxel.y + dy, voxel.z + dz});
        const glm::vec3 f = local - glm::floor(local);
        if (glm::any(glm::lessThan(f, glm::vec3(0.01f))) || glm::any(glm::greaterThan(f, glm::vec3(0.99f)))) continue;
        if (onlyLevel >= 0 && *level != onlyLevel) continue;
        expected.insert({*level, voxel.x, voxel.y, voxel.z});
    }
    SurfaceCoverage result;
    result.expected = expected.size();
    for (const auto& [level, x, y, z] : expected) {
        if (albedo[texelIndex(volume, {x, y, z}, level)].a > 0.0f) ++result.covered;
    }
    // Outside the centre that a finer level covers (propagation fills it), every occupied
    // voxel must be next to a surface.
    const int v = volume.resolution();
    for (int level = 0; level < volume.levels(); ++level) {
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    const glm::vec3 centre = volume.voxelCenter({x, y, z}, level);
                    if (level > 0 && volume.finestLevelContaining(centre) != level) continue;
                    if (albedo[texelIndex(volume, {x, y, z}, level)].a > 0.0f &&
                            !nearSurface.count({level, x, y, z})) {
                        ++result.stray;
                    }
                }
    }
    return result;
}

// At multiplier 8 every voxel a wall passes through is occupied (the bound: 99%), and
// nothing is occupied farther than one voxel from a surface.
TEST_F(VoxelGpuTest, CornellSurfacesCoverTheirVoxels) {
    const scene::Scene scene = loadCornellBox();
    VoxelFrame frame(scene, thesisAllocation(), {32, 32});
    const SurfaceCoverage coverage = surfaceCoverage(scene, frame, -1);
    ASSERT_GT(coverage.expected, 100u);
    EXPECT_GE(coverage.share(), 0.99)
            << coverage.covered << " of " << coverage.expected << " voxels the walls pass through are occupied";
    EXPECT_EQ(coverage.stray, 0) << "voxels occupied away from any surface";
}

// Five levels at multiplier 8: one raster over the coarsest level has half a pixel per finest
// voxel edge and leaves most of the finest level's voxels on a floor empty (the holes light
// passes through); voxel.raster_per_level rasterizes each level over its own extent and
// fills them all, and nothing off the floor.
TEST_F(VoxelGpuTest, RasterPerLevelFillsTheFinestOfFiveLevels) {
    scene::Scene scene;
    scene.materials.emplace_back();
    addPrimitive(scene, horizontalSquare(1.0f, 0.0f));
    // The cascade centres on the camera: just above the floor, so the finest level holds it.
    scene.cameras.push_back(lookAtCamera({0.013f, 0.004f, 0.007f}, {0.5f, 0.0f, 0.5f}, 60.0f));
    addDefaults(scene);
    Settings settings = thesisAllocation();
    settings.voxel.levels = 5;
    settings.voxel.resolution = 32;
    settings.voxel.multiplier = 8;

    struct FloorVoxels {
        int expected = 0, covered = 0, stray = 0;
    };
    auto finestLevelFloor = [&](bool perLevel) {
        settings.voxel.rasterPerLevel = perLevel;
        VoxelFrame frame(scene, settings, {16, 16});
        const voxel::CascadeVolume& volume = frame.manager().volume();
        const auto albedo = readVolume(frame.manager().textures().albedo, volume);
        const float layerPosition = (0.0f - volume.origin(0).y) / volume.voxelSize(0);
        const int layer = int(std::floor(layerPosition));
        // A floor lying on a voxel face may be stored in either neighbour.
        const float inLayer = layerPosition - float(layer);
        const int below = inLayer < 0.01f ? layer - 1 : layer;
        const int above = inLayer > 0.99f ? layer + 1 : layer;
        FloorVoxels result;
        const int v = volume.resolution();
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    const bool occupied = albedo[texelIndex(volume, {x, y, z}, 0)].a > 0.0f;
                    if (y < below || y > above) {
                        result.stray += occupied ? 1 : 0;
                        continue;
                    }
                    if (y != layer) continue;
                    ++result.expected;
                    const bool neighbour = (below < layer &&
                            albedo[texelIndex(volume, {x, below, z}, 0)].a > 0.0f) ||
                            (above > layer && albedo[texelIndex(volume, {x, above, z}, 0)].a > 0.0f);
                    result.covered += occupied || neighbour ? 1 : 0;
                }
        return result;
    };
    const FloorVoxels holes = finestLevelFloor(false);
    const FloorVoxels filled = finestLevelFloor(true);

    ASSERT_EQ(filled.expected, 32 * 32) << "the floor must cross the whole finest level";
    EXPECT_LT(holes.covered, holes.expected / 2) << "one raster over the coarsest level: "
            << holes.covered << " of " << holes.expected << " finest floor voxels occupied";
    EXPECT_EQ(filled.covered, filled.expected) << "a raster per level: " << filled.covered
            << " of " << filled.expected << " finest floor voxels occupied";
    EXPECT_EQ(filled.stray, 0) << "finest voxels occupied off the floor";
}

// A 2 m grey (albedo 0.5) square at y = 0.013 m under a directional light, seen from `eye`.
scene::Scene sunlitGreyPlane(const glm::vec3& eye) {
    scene::Scene scene;
    scene::Material grey;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    scene.materials.push_back(grey);
    addPrimitive(scene, horizontalSquare(1.0f, 0.013f));
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 2.0f;
    scene.lights.push_back(sun);
    scene.cameras.push_back(lookAtCamera(eye, {0.0f, 0.0f, 0.0f}, 60.0f));
    return scene;
}

// The plane's irradiance E = I cos(theta), the same everywhere.
float sunlitPlaneIrradiance(const scene::Scene& scene) {
    const scene::Light& sun = scene.lights.front();
    return sun.intensity * -sun.direction.y;
}

// Calls visit(texel index) for every voxel that voxelization wrote directly (the finest level
// holding its centre: propagation, which dilutes by coverage, wrote the others) whose centre
// lies within half - one voxel size of the origin in x and in z: a voxel away from the edges of
// a plane of that half-size, whose area, counted from raster pixel centres, would be off by up
// to half a pixel along an edge.
template <typename Visit>
void forEachDirectVoxelInside(const voxel::CascadeVolume& volume, float half, Visit visit) {
    const int v = volume.resolution();
    for (int level = 0; level < volume.levels(); ++level)
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    const glm::vec3 centre = volume.voxelCenter({x, y, z}, level);
                    if (volume.finestLevelContaining(centre) != level) continue;
                    const float margin = half - volume.voxelSize(level);
                    if (std::abs(centre.x) > margin || std::abs(centre.z) > margin) continue;
                    visit(texelIndex(volume, {x, y, z}, level));
                }
}

// Under a directional light a plane has the same irradiance E = I cos(theta) everywhere.
// The thesis' fragment mean reads it exactly (half-float precision: 0.1%); the flux/area
// injection matches it on average (flux is conserved) and per voxel to within the share of
// light-view pixels that straddle voxel borders.
TEST_F(VoxelGpuTest, PlaneUnderDirectionalLightHasAnalyticIrradiance) {
    const scene::Scene scene = sunlitGreyPlane({0.0f, 1.5f, 1.5f});
    const float expectedE = sunlitPlaneIrradiance(scene);

    for (const bool fragmentMean : {true, false}) {
        Settings settings = thesisAllocation();
        settings.voxel.injectFragmentMean = fragmentMean;
        settings.voxel.injectResolution = fragmentMean ? 0 : 1024;
        VoxelFrame frame(scene, settings, {32, 32});
        const voxel::CascadeVolume& volume = frame.manager().volume();
        const auto albedo = readVolume(frame.manager().textures().albedo, volume);
        const auto irradiance = readVolume(frame.manager().textures().irradiance, volume);
        double sum = 0.0;
        int count = 0;
        float worst = 0.0f;
        forEachDirectVoxelInside(volume, 1.0f, [&](std::size_t i) {
            if (albedo[i].a <= 0.0f) return;
            EXPECT_NEAR(albedo[i].r, 0.5f, 0.001f);
            const float e = irradiance[i].r / frame.exposure();
            sum += e;
            worst = std::max(worst, std::abs(e - expectedE) / expectedE);
            ++count;
        });
        ASSERT_GT(count, 50) << "the plane should cross the cascade";
        EXPECT_NEAR(sum / count, expectedE, 0.01 * expectedE) << "mean over the plane, fragmentMean="
                                                            << fragmentMean;
        // Fragment mean: every voxel exact to half-float precision. Flux/area: a voxel spans
        // ~15 light pixels per axis at 1024, so a straddling row or column moves it by ~7%.
        EXPECT_LT(worst, fragmentMean ? 0.002f : 0.08f) << "worst voxel, fragmentMean=" << fragmentMean;
    }
}

// A plane tilted against the grid crosses many voxels only partly. Each of them must read
// the plane's irradiance (the stored irradiance, premultiplied by coverage, over coverage),
// so that a cone, which takes coverage x rho E from it, receives the flux the plane got
// there: no more, no less. inject_finalize.comp stores the summed flux (per face area) of a
// voxel covered less than a face as it is, which is E x coverage; dividing it by the voxel's
// area as well read 1.7 E over these voxels (measured).
TEST_F(VoxelGpuTest, PartlyCoveredVoxelsOfATiltedPlaneReadItsIrradiance) {
    scene::Scene scene = sunlitGreyPlane({0.2f, 0.4f, 0.1f});
    scene.primitives.clear();
    scene.instances.clear();
    scene.bounds = {};
    scene::Primitive plane = horizontalSquare(1.0f, 0.0f);
    const float tilt = 0.45f;   // radians about z: the plane's normal is (-sin, cos, 0)
    const glm::vec3 normal(-std::sin(tilt), std::cos(tilt), 0.0f);
    for (glm::vec3& p : plane.positions) {
        p = glm::vec3(p.x * std::cos(tilt), p.x * std::sin(tilt) + 0.013f, p.z);
    }
    for (glm::vec3& n : plane.normals) n = normal;
    addPrimitive(scene, std::move(plane));
    const scene::Light& sun = scene.lights.front();
    const float expectedE = sun.intensity * glm::dot(normal, -sun.direction);
    ASSERT_GT(expectedE, 0.0f);

    // The default plan, each level voxelized over its own extent (as the sunlit floor below):
    // every level's voxels get the same raster samples, so their areas are measured alike.
    Settings settings;
    settings.voxel.rasterPerLevel = true;
    VoxelFrame frame(scene, settings, {32, 32});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    const auto irradiance = readVolume(frame.manager().textures().irradiance, volume);
    double sum = 0.0;
    int partly = 0;
    // The tilted plane reaches 0.9 m along x.
    forEachDirectVoxelInside(volume, 0.9f, [&](std::size_t i) {
        const float coverage = albedo[i].a;
        if (coverage < 0.3f || coverage > 0.9f) return;
        sum += irradiance[i].r / coverage / frame.exposure();
        ++partly;
    });
    ASSERT_GT(partly, 50) << "the tilted plane should cross many voxels partly";
    std::printf("partly covered voxels %d, mean E %.4f of %.4f\n", partly, sum / partly,
            double(expectedE));
    EXPECT_NEAR(sum / partly, expectedE, 0.05 * expectedE);
}

// The default (adaptive) plan injects through light views fine enough for its finest voxels:
// every finest-level voxel inside a sunlit floor holds the floor's irradiance. With the
// thesis' v light pixels over the scene, each pixel (6 cm here) covered about 14 x 14 of the
// 4 mm voxels and its one fragment lit only one of them (1022 of 1024 came out under half the
// floor's irradiance): rows of unlit voxels, as on Sponza's court.
TEST_F(VoxelGpuTest, SunlitFloorLightsEveryFinestVoxelOfTheAdaptivePlan) {
    const scene::Scene scene = sunlitGreyPlane({0.2f, 0.3f, 0.1f});
    const float expectedE = sunlitPlaneIrradiance(scene);

    Settings settings;
    ASSERT_EQ(settings.plan, PLAN_ADAPTIVE);
    // A flat floor gets six levels; each voxelized over its own extent, the finest (4 mm
    // voxels) is occupied wherever the floor is, so only injection can leave one dark.
    settings.voxel.rasterPerLevel = true;
    VoxelFrame frame(scene, settings, {32, 32});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    const auto irradiance = readVolume(frame.manager().textures().irradiance, volume);
    const int v = volume.resolution();
    double sum = 0.0;
    int count = 0, dark = 0;
    for (int z = 0; z < v; ++z)
        for (int y = 0; y < v; ++y)
            for (int x = 0; x < v; ++x) {
                const std::size_t i = texelIndex(volume, {x, y, z}, 0);
                if (albedo[i].a <= 0.0f) continue;
                const glm::vec3 centre = volume.voxelCenter({x, y, z}, 0);
                const float margin = 1.0f - volume.voxelSize(0);
                if (std::abs(centre.x) > margin || std::abs(centre.z) > margin) continue;
                const float e = irradiance[i].r / frame.exposure();
                sum += e;
                dark += e < 0.5f * expectedE ? 1 : 0;
                ++count;
            }
    ASSERT_GT(count, 500) << "the finest level, centred near the camera, should lie on the floor";
    std::printf("finest voxels on the floor %d, under half the irradiance %d, mean E %.4f of %.4f\n",
            count, dark, sum / count, double(expectedE));
    EXPECT_EQ(dark, 0) << "finest voxels on the sunlit floor left (nearly) unlit";
    EXPECT_NEAR(sum / count, expectedE, 0.05 * expectedE);
}

// Propagation conserves the coverage-weighted colour: a coarse level's centre holds, summed,
// one eighth of the finer level's albedo x coverage, which the albedo texture stores
// premultiplied (1%, half-float sums). This is the thesis' mean propagation; the default
// max-axis coverage rescales each coarse voxel to the opacity a ray meets and so adds colour.
TEST_F(VoxelGpuTest, PropagationConservesCoverageWeightedColour) {
    const scene::Scene scene = loadCornellBox();
    scene::Scene inside = scene;
    // From the box's centre with a 0.3 m finest level, the box straddles all three levels.
    inside.cameras[0] = lookAtCamera({0.278f, 0.27f, -0.28f}, {0.278f, 0.27f, -0.6f}, 60.0f);
    Settings settings = thesisAllocation();
    settings.voxel.extent = 0.3f;
    settings.voxel.coverageMaxAxis = false;
    VoxelFrame frame(inside, settings, {32, 32});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    const int v = volume.resolution();
    for (int level = 1; level < volume.levels(); ++level) {
        glm::dvec3 fine(0.0), coarse(0.0);
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    fine += glm::dvec3(albedo[texelIndex(volume, {x, y, z}, level - 1)]);
                }
        for (int z = v / 4; z < 3 * v / 4; ++z)
            for (int y = v / 4; y < 3 * v / 4; ++y)
                for (int x = v / 4; x < 3 * v / 4; ++x) {
                    coarse += glm::dvec3(albedo[texelIndex(volume, {x, y, z}, level)]);
                }
        ASSERT_GT(fine.r, 0.0) << "level " << level - 1 << " is empty";
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(coarse[c] * 8.0, fine[c], 0.01 * fine[c]) << "level " << level << " channel " << c;
        }
    }
}

// Each voxel of a flat surface knows where in it the surface lies (normal.w, the signed
// offset from the voxel centre along the normal, in voxel sizes), at the level it was
// voxelized at and after propagation: a horizontal square at y = 0.013 m, probed in every
// level's voxels it passes through. Tolerance: one snorm8 step (1/127) from the stochastic
// rounding of each stored running average, doubled for the levels propagated from it.
TEST_F(VoxelGpuTest, VoxelsLocateTheirFlatSurface) {
    scene::Scene scene;
    scene.materials.push_back(scene::Material{});
    constexpr float kPlaneY = 0.013f;
    addPrimitive(scene, horizontalSquare(1.0f, kPlaneY));
    // 0.2 m above the square: the finer levels around the camera reach it too.
    scene.cameras.push_back(lookAtCamera({0.0f, 0.2f, 0.2f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    addDefaults(scene);
    VoxelFrame frame(scene, thesisAllocation(), {32, 32});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    const auto normal = readVolume(frame.manager().textures().normal, volume);
    const int v = volume.resolution();
    int direct = 0, propagated = 0;
    for (int level = 0; level < volume.levels(); ++level)
        for (int z = 0; z < v; ++z)
            for (int y = 0; y < v; ++y)
                for (int x = 0; x < v; ++x) {
                    const std::size_t i = texelIndex(volume, {x, y, z}, level);
                    const glm::vec3 centre = volume.voxelCenter({x, y, z}, level);
                    const float size = volume.voxelSize(level);
                    // Voxels well inside the square, whose slab holds the plane.
                    if (albedo[i].a <= 0.0f || std::abs(centre.y - kPlaneY) > 0.5f * size ||
                            std::abs(centre.x) > 0.9f || std::abs(centre.z) > 0.9f) {
                        continue;
                    }
                    const float expected = (kPlaneY - centre.y) / size;
                    const bool filled = level > 0 && volume.finestLevelContaining(centre) != level;
                    const float tolerance = (filled ? 2.0f : 1.0f) / 127.0f + 1e-3f;
                    EXPECT_NEAR(normal[i].y, 1.0f, 0.02f) << "Probe at level " << level;
                    EXPECT_NEAR(normal[i].w, expected, tolerance)
                            << "Probe at (" << x << "," << y << "," << z << ") level " << level
                            << (filled ? " (propagated)" : "");
                    ++(filled ? propagated : direct);
                }
    std::printf("plane offsets probed in %d voxelized and %d propagated voxels\n", direct, propagated);
    EXPECT_GT(direct, 50);
    EXPECT_GT(propagated, 20);
}

// Cone tracing's walk learns from the normal texel alone whether a voxel is occupied and, if
// not, how far the nearest occupied voxel is (voxel_plane.glsl, EmptyDistancePass.h). Two
// coincident squares facing opposite ways cancel both the normal and the offset of the voxels
// holding them (the surface lies on level 0's voxel centres, so their offsets average to zero
// as well); without a marker those voxels would store an empty texel.
// At 32^3 and at 64^3, with small squares just past the level's middle in x and just short of
// it in z, so the distances above them are counted from one side of the middle only.
class EmptyDistanceGpuTest : public VoxelGpuTest, public ::testing::WithParamInterface<int> {};

TEST_P(EmptyDistanceGpuTest, NormalTexelTellsOccupiedVoxelsAndTheDistanceToThem) {
    const int resolution = GetParam();
    scene::Scene scene;
    scene.materials.push_back(scene::Material{});
    scene.cameras.push_back(lookAtCamera({0.0f, 0.2f, 0.2f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    // One scene-centred level of v^3 voxels 2/v m wide.
    Settings settings = thesisAllocation();
    settings.voxel.resolution = resolution;
    settings.voxel.levels = 1;
    settings.voxel.sceneCentred = true;
    settings.voxel.extent = 2.0f;
    const float kCentreY = 1.0f / float(resolution);
    scene::Primitive up = horizontalSquare(0.9f, kCentreY);
    scene::Primitive down = up;
    down.normals.assign(down.normals.size(), glm::vec3(0.0f, -1.0f, 0.0f));
    down.indices = {0, 1, 2, 0, 2, 3};
    addPrimitive(scene, up);
    addPrimitive(scene, down);
    // Two small squares a voxel higher centre the scene's bounds, and so the level, a voxel
    // edge above the pair: the pair lies on a row of voxel centres. One lies just past the
    // level's middle in x, the other just short of it in z.
    for (const glm::vec3 offset : {glm::vec3(0.051f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -0.051f)}) {
        scene::Primitive small = horizontalSquare(0.05f, 3.0f * kCentreY);
        for (glm::vec3& p : small.positions) p += offset;
        small.localBounds = {};
        for (const glm::vec3& p : small.positions) small.localBounds.extend(p);
        addPrimitive(scene, small);
    }
    addDefaults(scene);
    VoxelFrame frame(scene, settings, {32, 32});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    ASSERT_EQ(volume.levels(), 1);
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    const auto normal = readVolume(frame.manager().textures().normal, volume);
    const int v = volume.resolution();
    ASSERT_EQ(v, resolution);
    std::vector<char> occupied(std::size_t(v) * v * v, 0);
    std::size_t occupiedCount = 0;
    for (int z = 0; z < v; ++z)
        for (int y = 0; y < v; ++y)
            for (int x = 0; x < v; ++x) {
                if (albedo[texelIndex(volume, {x, y, z}, 0)].a > 0.0f) {
                    occupied[(std::size_t(z) * v + y) * v + x] = 1;
                    ++occupiedCount;
                }
            }
    constexpr int kCap = 4;   // kEmptyDistanceCap
    // The Chebyshev distance to the nearest occupied voxel, counted shell by shell.
    const auto distanceAt = [&](int x, int y, int z) {
        for (int r = 1; r <= kCap; ++r) {
            for (int dz = -r; dz <= r; ++dz)
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx) {
                        if (std::max(std::abs(dx), std::max(std::abs(dy), std::abs(dz))) != r) continue;
                        const int ox = x + dx, oy = y + dy, oz = z + dz;
                        if (ox < 0 || oy < 0 || oz < 0 || ox >= v || oy >= v || oz >= v) continue;
                        if (occupied[(std::size_t(oz) * v + oy) * v + ox]) return r;
                    }
        }
        return kCap + 1;
    };
    int cancelled = 0, wrongOccupied = 0, wrongEmpty = 0, far = 0;
    for (int z = 0; z < v; ++z)
        for (int y = 0; y < v; ++y)
            for (int x = 0; x < v; ++x) {
                const std::size_t t = texelIndex(volume, {x, y, z}, 0);
                const glm::vec4 texel = normal[t];
                const bool markedOccupied = glm::vec3(texel) != glm::vec3(0.0f) || texel.w > 0.0f;
                if (albedo[t].a > 0.0f) {
                    if (glm::length(glm::vec3(texel)) < 0.1f) ++cancelled;
                    if (!markedOccupied) ++wrongOccupied;
                    continue;
                }
                const int distance = distanceAt(x, y, z);
                far += distance > kCap ? 1 : 0;
                if (markedOccupied || std::lround(-texel.w * 127.0f) != distance) ++wrongEmpty;
            }
    std::printf("%zu occupied voxels, %d with cancelled normals; %d empty voxels farther than %d\n",
            occupiedCount, cancelled, far, kCap);
    EXPECT_GT(occupiedCount, 500u);
    EXPECT_GT(cancelled, int(occupiedCount) / 2) << "the two faces should cancel in most voxels";
    EXPECT_GT(far, 1000);
    EXPECT_EQ(wrongOccupied, 0) << "occupied voxels the walk would take for empty";
    EXPECT_EQ(wrongEmpty, 0) << "empty voxels whose texel gives the wrong distance";
}

INSTANTIATE_TEST_SUITE_P(Resolutions, EmptyDistanceGpuTest, ::testing::Values(32, 64),
        [](const auto& info) { return "v" + std::to_string(info.param); });

// The pyramid above the coarsest level averages its reflected light per face: face f of mip m
// summed over its texels holds 1/8^(m+1) of the coarsest level's rho E x coverage x the area
// its mean normal shows face f (max(+-n_axis, 0)) summed over its voxels, and of that area
// (1%, half-float sums); every face holds a part of the box, none half of it. A propagated
// coarsest level (a cascade of three) gives every face the whole coverage: the one average.
class PyramidFacesGpuTest : public GpuTest, public ::testing::WithParamInterface<int> {};

TEST_P(PyramidFacesGpuTest, PyramidConservesTheCoarsestLightPerFace) {
    const scene::Scene scene = loadCornellBox();
    Settings settings = thesisAllocation();
    settings.voxel.levels = GetParam();
    VoxelFrame frame(scene, settings, {32, 32});
    const voxel::VoxelTextures& textures = frame.manager().textures();
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(textures.albedo, volume);
    const auto irradiance = readVolume(textures.irradiance, volume);
    const auto normal = readVolume(textures.normal, volume);
    const int v = volume.resolution();
    const int coarsest = volume.levels() - 1;
    glm::dvec4 level[VOXEL_FACES] = {};
    double coverage = 0.0;
    for (int z = 0; z < v; ++z)
        for (int y = 0; y < v; ++y)
            for (int x = 0; x < v; ++x) {
                const std::size_t i = texelIndex(volume, {x, y, z}, coarsest);
                if (albedo[i].a <= 0.0f) continue;
                const glm::vec3 reflected = glm::vec3(albedo[i]) * glm::vec3(irradiance[i]) / albedo[i].a;
                coverage += double(albedo[i].a);
                for (int face = 0; face < VOXEL_FACES; ++face) {
                    const float n = normal[i][face / 2];
                    const double shown =
                            volume.levels() == 1 ? std::max(face % 2 == 0 ? n : -n, 0.0f) : 1.0;
                    level[face] += shown * glm::dvec4(glm::dvec3(reflected), double(albedo[i].a));
                }
            }
    ASSERT_EQ(volume.levels(), GetParam());
    for (int face = 0; face < VOXEL_FACES; ++face) {
        ASSERT_GT(level[face].a, 0.0) << "face " << face;   // the box shows every face a wall
        if (volume.levels() == 1) EXPECT_LT(level[face].a, 0.5 * coverage) << "face " << face;
    }
    for (int mip = 0; mip < textures.pyramidLevels(); ++mip) {
        const int size = v / (2 << mip);
        std::vector<glm::vec4> texels(
                std::size_t(size) * VOXEL_FACES * std::size_t(size) * std::size_t(size));
        glGetTextureImage(textures.pyramid.id(), mip, GL_RGBA, GL_FLOAT,
                GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
        glm::dvec4 sum[VOXEL_FACES] = {};
        for (std::size_t t = 0; t < texels.size(); ++t) {
            sum[(t % std::size_t(size * VOXEL_FACES)) / std::size_t(size)] += glm::dvec4(texels[t]);
        }
        const double scale = std::pow(8.0, double(mip + 1));
        for (int face = 0; face < VOXEL_FACES; ++face) {
            for (int c = 0; c < 4; ++c) {
                EXPECT_NEAR(sum[face][c] * scale, level[face][c], 0.01 * level[face][c])
                        << "mip " << mip << " face " << face << " channel " << c;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Levels, PyramidFacesGpuTest, ::testing::Values(1, 3),
        [](const auto& info) { return "levels" + std::to_string(info.param); });

// Every fragment of many coincident quads lands in the same few voxels: the spinlock must
// neither hang (ctest's timeout would) nor lose an update. 64 quads alternate red and blue,
// so each voxel's mean albedo is exactly half of each.
TEST_F(VoxelGpuTest, SpinlockAveragesUnderHeavyContention) {
    scene::Scene scene;
    scene::Material red, blue;
    red.baseColorFactor = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    blue.baseColorFactor = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    scene.materials = {red, blue};
    for (int i = 0; i < 64; ++i) {
        scene::Primitive quad = horizontalSquare(0.5f, 0.1f);
        quad.material = i % 2;
        addPrimitive(scene, quad);
    }
    scene.cameras.push_back(lookAtCamera({0.0f, 1.0f, 0.01f}, {0.0f, 0.0f, 0.0f}, 60.0f));
    addDefaults(scene);
    Settings settings = thesisAllocation();
    settings.voxel.resolution = 4;
    settings.voxel.levels = 1;
    settings.voxel.multiplier = 16;
    settings.voxel.extent = 2.0f;
    VoxelFrame frame(scene, settings, {16, 16});
    const voxel::CascadeVolume& volume = frame.manager().volume();
    const auto albedo = readVolume(frame.manager().textures().albedo, volume);
    int occupied = 0;
    for (const glm::vec4& a : albedo) {
        if (a.a <= 0.0f) continue;
        ++occupied;
        // 16384 fragments per voxel (64 quads x 16 x 16 raster pixels): far beyond the 2048
        // where plain half-float rounding stalls. Stochastic rounding keeps the mean unbiased;
        // its random walk over 16384 updates of 1/2 ulp (2^-12) has a spread of about 0.016,
        // so 0.04 is 2.5 sigma.
        EXPECT_NEAR(a.r, 0.5f, 0.04f);
        EXPECT_NEAR(a.b, 0.5f, 0.04f);
    }
    EXPECT_GE(occupied, 4);
}

TEST_F(VoxelGpuTest, MemoryMatchesAllocationAndThesisBudget) {
    const scene::Scene scene = loadCornellBox();
    VoxelFrame frame(scene, thesisAllocation(), {32, 32});
    // The report reads what was allocated (gl/MemoryRegistry.h).
    std::size_t volumeBytes = 0;
    for (const char* volume : {"voxel/albedo", "voxel/normal", "voxel/irradiance", "voxel/helper",
                 "voxel/lock", "voxel/pyramid"}) {
        volumeBytes += bytesWithPrefix(frame.renderer().memory(), volume);
    }
    // 5 textures of v^3 l texels: 3 x RGBA16F (8 B) + RGBA8_SNORM (4 B) + R32UI (4 B), and
    // the RGBA16F pyramid above the coarsest level, 6 faces of 16^3 + 8^3 + 4^3 + 2^3 + 1
    // texels.
    EXPECT_EQ(volumeBytes,
            std::size_t(32) * 32 * 32 * 3 * 32 + (4096 + 512 + 64 + 8 + 1) * 8 * VOXEL_FACES);
    EXPECT_LE(double(volumeBytes), 3.46e6) << "the thesis needs 3.46 MB for the same data";
}

// One-bounce colour bleeding: the floor's indirect light is redder beside the red (left)
// wall and greener beside the green (right) wall. Probes are the floor's left and right
// quarters in the bottom rows of the classic view.
TEST_F(VoxelGpuTest, CornellFloorBleedsWallColours) {
    const scene::Scene scene = loadCornellBox();
    VoxelFrame frame(scene, thesisAllocation(), {96, 96}, render::OutputComponent::Indirect);
    const core::Image image = frame.image();
    ASSERT_TRUE(core::allFinite(image));
    auto regionMean = [&](int x0, int x1, int y0, int y1) {
        glm::dvec3 sum(0.0);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) sum += glm::dvec3(image.at(x, y));
        return sum / double((x1 - x0) * (y1 - y0));
    };
    const glm::dvec3 left = regionMean(8, 24, 86, 94), right = regionMean(72, 88, 86, 94);
    ASSERT_GT(left.g, 0.0);
    ASSERT_GT(right.r, 0.0);
    // Ratios, not absolutes: the left floor's red/green exceeds the right floor's by 20%,
    // and the right floor's green/red exceeds the left's by 20%.
    EXPECT_GT(left.r / left.g, 1.2 * right.r / right.g) << "left " << left.r << "," << left.g
                                                        << " right " << right.r << "," << right.g;
    EXPECT_GT(right.g / right.r, 1.2 * left.g / left.r);
}

// The cascade holds the whole scene around the camera, not just the view: narrow views of
// the floor beside the red wall and beside the green wall, neither wall in the picture, still
// show each wall's colour bleeding onto its side of the floor.
TEST_F(VoxelGpuTest, OffscreenWallStillLightsTheFloor) {
    auto indirectAt = [&](const glm::vec3& floorPoint) {
        scene::Scene scene = loadCornellBox();
        // 20 degrees wide from 25 cm above: the view spans +-5 cm around the point, which is
        // 6 cm from the wall, so no wall is in the picture.
        scene.cameras[0] = lookAtCamera(floorPoint + glm::vec3(0.0f, 0.25f, 0.17f), floorPoint, 20.0f);
        Settings settings = thesisAllocation();
        settings.specular = 0.0f;
        constexpr int kSize = 32;
        VoxelFrame frame(scene, settings, {kSize, kSize}, render::OutputComponent::Indirect);
        const core::Image image = frame.image();
        glm::dvec3 sum(0.0);
        for (int y = 12; y < 20; ++y)
            for (int x = 12; x < 20; ++x) sum += glm::dvec3(image.at(x, y));
        return sum / 64.0;
    };
    const glm::dvec3 redSide = indirectAt({0.06f, 0.0f, -0.15f});
    const glm::dvec3 greenSide = indirectAt({0.496f, 0.0f, -0.15f});
    ASSERT_GT(redSide.g, 0.0) << "the floor receives indirect light with the wall out of view";
    ASSERT_GT(greenSide.r, 0.0);
    // The reference renderer gives R/G = 1.16 beside the red wall and 0.56 beside the green
    // one (ratio 2.1); 1.08 keeps the direction with room for the voxel artefacts, while a
    // cascade without the off-screen walls would give ~1.0.
    std::printf("off-screen bleeding: red side R/G %.3f, green side R/G %.3f\n",
            redSide.r / redSide.g, greenSide.r / greenSide.g);
    EXPECT_GT((redSide.r / redSide.g) / (greenSide.r / greenSide.g), 1.08)
            << "red side R/G " << redSide.r / redSide.g << ", green side R/G " << greenSide.r / greenSide.g;
}

// Scored against the path tracer (one bounce, the Lambertian reference): the energy of the
// indirect component must be within the 0.85-1.15 of the reference's. The relative
// RMSE is printed for the record (voxel artefacts keep it far above the reference's noise).
TEST_F(VoxelGpuTest, CornellIndirectEnergyMatchesReference) {
    const scene::Scene scene = loadCornellBox();
    Settings settings = thesisAllocation();
    settings.specular = 0.0f;
    constexpr int kSize = 96;
    VoxelFrame frame(scene, settings, {kSize, kSize}, render::OutputComponent::Indirect);
    const core::Image voxel = frame.image();
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 64;
    referenceSettings.bounces = 1;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    const reference::ReferenceResult truth =
            reference::renderReference(scene, camera, kSize, kSize, referenceSettings);
    ASSERT_FALSE(truth.indirect.empty());
    const reference::ImageErrors errors =
            reference::measureImageError(voxel, truth.indirect, truth.coverage);
    std::printf("voxel GI vs reference, Cornell indirect: relative RMSE %.3f, energy ratio %.3f "
                "(reference noise %.3f)\n", errors.relativeRmse, errors.energyRatio,
            truth.noise.indirect);
    EXPECT_GT(errors.energyRatio, 0.85);
    EXPECT_LT(errors.energyRatio, 1.15);
}

struct DebugGolden {
    const char* name;
    render::OutputComponent output;
    int level;
};

class VoxelGoldenGpuTest : public GpuTest, public ::testing::WithParamInterface<DebugGolden> {};

TEST_P(VoxelGoldenGpuTest, CornellView) {
    const scene::Scene scene = loadCornellBox();
    Settings settings = thesisAllocation();
    settings.voxel.debugLevel = GetParam().level;
    VoxelFrame frame(scene, settings, {128, 128}, GetParam().output);
    const core::Image image = frame.image();
    ASSERT_TRUE(core::allFinite(image));
    // Spinlock order changes half-float rounding of the running averages between runs, and
    // cone tracing magnifies it slightly: allow 0.5% of pixels over 6/255 and a mean of 1/255.
    ImageTolerance tolerance;
    tolerance.maxFailingFraction = 0.005;
    tolerance.maxMeanAbsDiff = 1.0;
    // Normals are 8-bit snorm, rounded stochastically in an order that depends on thread
    // scheduling: one snorm step (1/127) is up to 8/255 after the 0.5 + 0.5n and sRGB encodes.
    if (GetParam().output == render::OutputComponent::VoxelNormal) tolerance.pixelThreshold = 9;
    const std::string failure = compareWithReference(image, std::string("frame/") + GetParam().name, tolerance);
    EXPECT_TRUE(failure.empty()) << failure;
}

INSTANTIATE_TEST_SUITE_P(DebugViews, VoxelGoldenGpuTest,
        ::testing::Values(DebugGolden{"cornell_voxel_final", render::OutputComponent::Final, 0},
                DebugGolden{"cornell_voxel_indirect", render::OutputComponent::Indirect, 0},
                DebugGolden{"cornell_voxel_albedo_l2", render::OutputComponent::VoxelAlbedo, 2},
                DebugGolden{"cornell_voxel_irradiance_l2", render::OutputComponent::VoxelIrradiance, 2},
                DebugGolden{"cornell_voxel_normal_l2", render::OutputComponent::VoxelNormal, 2}),
        [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace gi::test
