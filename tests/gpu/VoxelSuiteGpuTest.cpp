// Voxel GI at default settings against the path tracer on scenes of the accuracy suite
// (assets/scene_suite), indirect component from camera 0, 96x96, Lambertian, one bounce.
#include "GpuTest.h"
#include "TestScenes.h"

#include "gl/GpuProfiler.h"
#include "gl/ShaderLibrary.h"
#include "reference/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"
#include "scene/CameraView.h"

#include <cstdio>
#include <string>

namespace gi::test {
namespace {

constexpr int kSize = 96;

// The indirect component of a voxel-GI frame from the scene's camera `index`.
core::Image voxelIndirect(const scene::Scene& scene, const Settings& settings, int index) {
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[std::size_t(index)],
            1.0f, scene.bounds);
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    EXPECT_TRUE(renderer.setMode(render::GiMode::Voxel, error)) << error;
    gl::GpuProfiler profiler;
    renderer.render(camera, {kSize, kSize}, render::OutputComponent::Indirect, profiler);
    profiler.flush();
    return renderer.readback();
}

// The path tracer's indirect component from the scene's camera 0 (64 spp, one bounce).
reference::ReferenceResult referenceIndirect(const scene::Scene& scene) {
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    ReferenceSettings referenceSettings;
    referenceSettings.spp = 64;
    referenceSettings.bounces = 1;
    reference::ReferenceResult truth =
            reference::renderReference(scene, camera, kSize, kSize, referenceSettings);
    EXPECT_FALSE(truth.indirect.empty());
    return truth;
}

reference::ImageErrors voxelAgainst(const reference::ReferenceResult& truth,
        const scene::Scene& scene, const Settings& settings) {
    const core::Image voxel = voxelIndirect(scene, settings, 0);
    return reference::measureImageError(voxel, truth.indirect, truth.coverage);
}

reference::ImageErrors voxelAgainstReference(const scene::Scene& scene, const Settings& settings) {
    return voxelAgainst(referenceIndirect(scene), scene, settings);
}

// Mean indirect light (all pixels) of a voxel-GI frame from the scene's camera `index`.
double meanIndirect(const scene::Scene& scene, const Settings& settings, int index) {
    const core::Image image = voxelIndirect(scene, settings, index);
    double sum = 0.0;
    for (float value : image.rgb) sum += double(value);
    return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size());
}

// The defaults with Lambertian materials, as the path tracer renders them.
Settings lambertian() {
    Settings settings;
    settings.specular = 0.0f;
    return settings;
}

// `format` with one number in it, for printErrors' label.
std::string label(const char* format, double value) {
    char text[128];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// One line of a test's figures: `what`, then relative RMSE and energy ratio.
void printErrors(const std::string& what, const reference::ImageErrors& errors) {
    std::printf("%s: relative RMSE %.3f, energy ratio %.3f\n", what.c_str(), errors.relativeRmse,
            errors.energyRatio);
}

// The scene's voxel GI at `settings` against the path tracer, printed as `what`, held to a
// relative RMSE under maxRmse and an energy ratio between lowEnergy and highEnergy.
void expectVoxelWithin(const scene::Scene& scene, const Settings& settings,
        const std::string& what, double maxRmse, double lowEnergy, double highEnergy) {
    const reference::ImageErrors errors = voxelAgainstReference(scene, settings);
    printErrors(what, errors);
    EXPECT_LT(errors.relativeRmse, maxRmse) << what;
    EXPECT_GT(errors.energyRatio, lowEnergy) << what;
    EXPECT_LT(errors.energyRatio, highEnergy) << what;
}

class VoxelSuiteGpuTest : public GpuTest {};

// Two closed rooms share a wall one finest voxel thick; the light is in one of them, so the
// other (camera 1) must stay dark. Isotropic voxels average a wall's lit and dark sides
// wherever one voxel holds both (every level coarser than the finest), and show the dark
// room the mean; anisotropic voxels show each room its own side. With the pyramid read up
// to its first mip (wider texels average light across the wall whatever the voxels store),
// the dark room receives 0.072 of the lit room's mean indirect light with isotropic voxels
// and 0.017 with anisotropic ones.
TEST_F(VoxelSuiteGpuTest, AnisotropicVoxelsKeepTheWallBetweenTwoRooms) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/two_rooms_thin_wall.gltf");
    Settings settings = lambertian();
    settings.voxel.pyramidMips = 0;
    settings.voxel.oneLevelLimit = 0;   // the cascade, whose coarser levels hold both rooms
    for (const bool anisotropic : {false, true}) {
        settings.voxel.anisotropic = anisotropic;
        const double lit = meanIndirect(scene, settings, 0);
        const double dark = meanIndirect(scene, settings, 1);
        std::printf("two rooms, anisotropic %d: lit room %.4f, dark room %.4f, leak %.3f\n",
                int(anisotropic), lit, dark, dark / lit);
        ASSERT_GT(lit, 0.0);
        if (anisotropic) EXPECT_LT(dark / lit, 0.04);
    }
}

// voxel.light_read=surface: where a cone meets a surface, the faces of the light it meets
// (anisotropic voxels' faces, and the light pyramid's of either kind) are read as the surface
// met faces, so the wide read leaves out the sides of its texels' other surfaces that face the
// cone but not the light (in the lit room, the wall's and the partition's unlit flanks beside
// the lit floor). The lit room against the path tracer, 96x96, with the cone's faces and the
// surface's: anisotropic voxels relative RMSE 0.115 -> 0.093 (energy 0.918 -> 0.953),
// isotropic ones 0.094 -> 0.061 (0.929 -> 0.971).
TEST_F(VoxelSuiteGpuTest, SurfaceLightReadBringsTheLitRoomCloserToThePathTracer) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/two_rooms_thin_wall.gltf");
    const reference::ReferenceResult truth = referenceIndirect(scene);
    Settings settings = lambertian();
    for (const bool anisotropic : {false, true}) {
        settings.voxel.anisotropic = anisotropic;
        settings.voxel.lightRead = LIGHT_READ_CONE;
        const reference::ImageErrors cone = voxelAgainst(truth, scene, settings);
        settings.voxel.lightRead = LIGHT_READ_SURFACE;
        const reference::ImageErrors surface = voxelAgainst(truth, scene, settings);
        std::printf("two rooms, lit room, anisotropic %d: cone's faces %.3f / %.3f, surface's "
                    "faces %.3f / %.3f\n",
                int(anisotropic), cone.relativeRmse, cone.energyRatio, surface.relativeRmse,
                surface.energyRatio);
        EXPECT_LT(surface.relativeRmse, cone.relativeRmse - 0.01) << "anisotropic " << anisotropic;
        EXPECT_GT(surface.energyRatio, cone.energyRatio) << "anisotropic " << anisotropic;
    }
}

// The light pyramid above the coarsest level keeps each face apart (RadiancePyramidPass.h), and
// a wide cone reads the faces its directions see. It averaged every surface its texels held by
// coverage: on the spot-lit box a cone meeting the ceiling read the ceiling's light mixed with
// the walls' and blocks' flanks beside the spot's bright floor patch. The target at the
// defaults: relative RMSE 0.30, energy 0.9-1.1 (here 0.231 / 1.002; the scoreboard's 128x128:
// 0.383 / 0.887 with one average, 0.210 / 0.996 by faces).
TEST_F(VoxelSuiteGpuTest, PyramidReadByFacesLightsTheSpotBoxAsThePathTracer) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_spot.gltf");
    expectVoxelWithin(scene, lambertian(), "spot-lit box", 0.30, 0.9, 1.1);
}

// The adaptive plan holds the two rooms in one scene-centred level of 64^3
// (voxel.one_level_limit) at the finest voxel its cascade had: the wall is a whole voxel thick
// wherever a cone meets it, and the dark room stays under the 5 % of the lit room's
// mean indirect light. The cascade, whose coarser levels hold both sides of the wall in one
// voxel, lets more through.
TEST_F(VoxelSuiteGpuTest, OneLevelKeepsTheDarkRoomUnderFivePercent) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/two_rooms_thin_wall.gltf");
    Settings settings = lambertian();
    double leak[2] = {0.0, 0.0};
    for (const int limit : {0, 128}) {
        settings.voxel.oneLevelLimit = limit;
        const double lit = meanIndirect(scene, settings, 0);
        const double dark = meanIndirect(scene, settings, 1);
        ASSERT_GT(lit, 0.0);
        leak[limit > 0] = dark / lit;
        std::printf("two rooms, one-level limit %d: lit room %.4f, dark room %.4f, leak %.4f\n",
                limit, lit, dark, dark / lit);
    }
    EXPECT_LT(leak[1], 0.05);
    EXPECT_GT(leak[0], 1.5 * leak[1]);
}

// voxel.cone_offset moves the cones' origin off the surface: two voxels instead of one let
// the Cornell box's cones pass the voxels where its walls meet, and the box gathers more of
// its light (96x96 against the path tracer: energy 0.966 at one voxel, 1.007 at two).
TEST_F(VoxelSuiteGpuTest, LargerConeOffsetGathersMoreOfTheCornellBoxsLight) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_classic.gltf");
    Settings settings = lambertian();
    settings.voxel.coneOffset = 1.0f;
    const double near = meanIndirect(scene, settings, 0);
    settings.voxel.coneOffset = 2.0f;
    const double far = meanIndirect(scene, settings, 0);
    std::printf("Cornell box, mean indirect light: cone offset 1 voxel %.4f, 2 voxels %.4f\n",
            near, far);
    ASSERT_GT(near, 0.0);
    EXPECT_GT(far / near, 1.02);
}

// A closed white box around a point light: every wall is lit and sees only lit walls. The
// thesis' coverage propagation (the mean of 8 children) halved each wall's opacity per cascade
// level, so cones saw the walls of the coarser levels half transparent and half as bright, and
// the fixed plan kept 0.83 of the indirect energy; the most opaque axis' coverage keeps 1.00.
TEST_F(VoxelSuiteGpuTest, ClosedWhiteBoxKeepsItsIndirectEnergy) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/closed_white_box.gltf");
    for (const int plan : {PLAN_FIXED, PLAN_ADAPTIVE}) {
        Settings settings = lambertian();
        settings.plan = plan;
        expectVoxelWithin(scene, settings, label("closed white box, plan %.0f", plan), 0.12, 0.9,
                1.1);
    }
}

// The same box on the adaptive plan (one level): a wide cone reads the light it meets from
// the light pyramid. The mip whose texels are one cone diameter wide (the thesis) averages
// over about twice the cone's footprint and carries the bright wall under the lamp into the
// dim corners the cones mostly see. In this box it kept 0.956 of the energy at relative RMSE
// 0.056 against the default mip's (voxel.footprint, texels 0.6 diameters wide) 1.018 and
// 0.046; since cones stop at every floor they cross (cone_tracing.glsl's plane tolerance) both
// score alike here (0.046 and 0.044, energy 0.967 and 1.029), and the next test compares them
// where they differ. Since the walk starts at the cones' origin (voxel.walk_start) the box
// reads 1.035 (its corners, where the outer ring reads the wall across the edge higher up than
// the darker strip beside the edge that its band stands for: accuracy-analysis.md, 'The
// cones' walk from their origin'), its relative RMSE 0.045 as before: the upper bound was
// 1.03 until then.
TEST_F(VoxelSuiteGpuTest, ReadingTheConesOwnFootprintKeepsTheClosedBoxEnergy) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/closed_white_box.gltf");
    const Settings settings = lambertian();
    expectVoxelWithin(scene, settings,
            label("closed white box, footprint %.2f", settings.voxel.footprint), 0.06, 0.97, 1.04);
}

// The default footprint against the thesis' on the classic Cornell box, whose lamp 1 cm under
// the ceiling makes one small bright patch that the thesis' wider read spreads over the
// ceiling and walls (scoreboard form, 128x128: 0.228 at energy 0.984 against 0.305 at 0.932).
TEST_F(VoxelSuiteGpuTest, ReadingTheConesOwnFootprintBeatsTheThesisReadOnTheCornellBox) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_classic.gltf");
    Settings settings = lambertian();
    const float defaultFootprint = settings.voxel.footprint;
    double thesisError = 0.0;
    for (const float footprint : {1.0f, defaultFootprint}) {
        settings.voxel.footprint = footprint;
        const reference::ImageErrors errors = voxelAgainstReference(scene, settings);
        printErrors(label("classic Cornell box, footprint %.2f", footprint), errors);
        if (footprint == 1.0f) {
            thesisError = errors.relativeRmse;
        } else {
            EXPECT_GT(errors.energyRatio, 0.95);
            EXPECT_LT(errors.energyRatio, 1.05);
            EXPECT_LT(errors.relativeRmse, thesisError - 0.03);
        }
    }
}

// On one level the cones' walk starts at their origin, a voxel off the surface (voxel.walk_start
// 0), instead of a voxel further out as in the thesis, which skipped every surface within two
// voxels: the blocks' feet in the open-front box lost the sunlit floor beside them, and points
// near the room's edges the wall across the edge (scoreboard form, 128x128 against 4096 spp:
// relative RMSE 0.233 -> 0.207).
TEST_F(VoxelSuiteGpuTest, WalkingFromTheOriginSeesTheSurfacesBesideAnEdge) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_open_front_sun.gltf");
    const reference::ReferenceResult truth = referenceIndirect(scene);
    Settings settings = lambertian();
    settings.voxel.walkStart = 1.0f;
    const reference::ImageErrors thesis = voxelAgainst(truth, scene, settings);
    printErrors("open-front box, walk from one voxel out", thesis);
    settings.voxel.walkStart = 0.0f;
    const reference::ImageErrors origin = voxelAgainst(truth, scene, settings);
    printErrors("open-front box, walk from the origin", origin);
    EXPECT_LT(origin.relativeRmse, thesis.relativeRmse - 0.01);
    EXPECT_GT(origin.energyRatio, 0.9);
    EXPECT_LT(origin.energyRatio, 1.1);
}

// The half-resolution trace upsampled with each texel weighted also by its distance from the
// pixel's own plane (voxel.upsample_plane): by depth alone a pixel beside an edge where two
// surfaces meet at one depth took the other surface's texels (the spot box's ceiling beside
// the walls, the blocks' tops beside their fronts).
TEST_F(VoxelSuiteGpuTest, UpsamplingKeepsToEachPixelsPlane) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/cornell_spot.gltf");
    const reference::ReferenceResult truth = referenceIndirect(scene);
    Settings settings = lambertian();
    settings.voxel.planeUpsample = false;
    const reference::ImageErrors depthOnly = voxelAgainst(truth, scene, settings);
    printErrors("spot box, upsampled by depth", depthOnly);
    settings.voxel.planeUpsample = true;
    const reference::ImageErrors plane = voxelAgainst(truth, scene, settings);
    printErrors("spot box, upsampled by depth and plane", plane);
    EXPECT_LT(plane.relativeRmse, depthOnly.relativeRmse - 0.003);
}

} // namespace
} // namespace gi::test
