// Texture-atlas GI against an analytic emitter: the area estimator's irradiance under an
// emitting square matches the point-to-rectangle form factor, and voxel visibility blocks the
// same emitter behind an opaque plate.
#include "AtlasGpuTestSupport.h"

#include "gi/voxel/VoxelizationManager.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace gi::test {
namespace {

// An emitting square (radiance L, black) 0.5 m above the centre of an equal floor square:
// E = L * integral cos cos / r^2 dA = 4 L (1/sqrt 2) atan(1/sqrt 2) = 1.7408 L (the
// point-to-rectangle form factor, e.g. Howell's catalogue, C-11, times pi). No lights.
scene::Scene emitterOverFloor(bool occluder) {
    scene::Scene scene;
    scene::Material grey, emitter, black;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    emitter.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    emitter.emissiveFactor = glm::vec3(2.0f, 1.0f, 0.5f);
    black.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    black.doubleSided = true;
    scene.materials = {grey, emitter, black};
    addPrimitive(scene, horizontalSquare(0.5f, 0.0f));
    scene::Primitive top = horizontalSquare(0.5f, 0.5f);
    top.indices = {0, 1, 2, 0, 2, 3}; // facing -Y
    top.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
    top.material = 1;
    addPrimitive(scene, top);
    if (occluder) {
        scene::Primitive plate = horizontalSquare(0.45f, 0.25f);
        plate.material = 2;
        addPrimitive(scene, plate);
    }
    scene.cameras.push_back(lookAtCamera({0.0f, 0.25f, 0.4f}, {0.0f, 0.25f, 0.0f}, 50.0f));
    return scene;
}

TEST_F(AtlasGpuTest, AreaEstimatorMatchesAnalyticEmitter) {
    const scene::Scene scene = emitterOverFloor(false);
    Settings settings = atlasSettings(256, 1024);
    settings.atlas.progressive = false;
    settings.atlas.rotate = false;
    AtlasFrame frame(scene, settings);
    frame.render({32, 32});
    const glm::dvec3 e =
            floorCentreIrradiance(frame.gi().atlas(), atlas::flattenScene(scene), frame.lit());
    const glm::dvec3 expected = kEmitterFormFactor * glm::dvec3(2.0, 1.0, 0.5);
    // ~500 of the 1024 Hammersley points land on the emitter and the integrand is smooth:
    // the quasi-Monte Carlo error is well under 1%; 2% also absorbs half-float storage.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(e[c], expected[c], 0.02 * expected[c])
                << "Probe at floor centre, channel " << c << ": expected " << expected[c]
                << " observed " << e[c];
    }
}

// The same emitter behind an opaque plate: with atlas.visibility=voxel the floor centre sees
// none of it through the occupancy of a voxel cascade; without visibility the plate changes
// nothing (the thesis ignores occlusion).
TEST_F(AtlasGpuTest, VoxelVisibilityBlocksAnOccludedEmitter) {
    const scene::Scene scene = emitterOverFloor(true);
    const atlas::AtlasMesh mesh = atlas::flattenScene(scene);
    Settings settings = atlasSettings(256, 256);
    settings.atlas.progressive = false;
    settings.voxel.resolution = 64;
    settings.voxel.levels = 1;
    settings.voxel.extent = 3.2f;
    const glm::ivec2 size(32, 32);
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);

    gl::ShaderLibrary shaders;
    scene::GpuScene gpuScene(scene);
    render::ShadowPass shadows;
    std::string error;
    ASSERT_TRUE(shadows.init(shaders, error)) << error;
    shadows.setLights(scene.lights, scene.bounds, settings.shadow);
    shader::FrameUniforms uniforms{};
    uniforms.viewProjection = camera.viewProjection();
    uniforms.inverseViewProjection = glm::inverse(uniforms.viewProjection);
    uniforms.view = camera.view;
    uniforms.cameraPosition = glm::vec4(camera.eye, 1.0f);
    uniforms.screen = glm::vec4(glm::vec2(size), 0.0f, 0.0f);
    uniforms.counts = glm::ivec4(0, OUTPUT_FINAL, 0, 0);
    const gl::Buffer frameUniforms = gl::createBuffer(sizeof uniforms, &uniforms, 0, "test/frame");
    gl::GpuProfiler profiler;
    shadows.execute({gpuScene}, profiler);

    voxel::VoxelizationManager voxels;
    ASSERT_TRUE(voxels.init(shaders, scene, error)) << error;
    ASSERT_TRUE(voxels.configure(settings, error)) << error;
    const GiFrameInputs voxelInputs{gpuScene, scene.lights, shadows, frameUniforms, camera, size};
    voxels.update(voxelInputs, profiler);
    const OccupancyVolume occupancy = voxels.occupancy();

    for (const int visibility : {ATLAS_VISIBILITY_NONE, ATLAS_VISIBILITY_VOXEL}) {
        settings.atlas.visibility = visibility;
        atlas::AtlasGi gi;
        ASSERT_TRUE(gi.init(shaders, scene, error)) << error;
        ASSERT_TRUE(gi.configure(settings, error)) << error;
        GiFrameInputs inputs{gpuScene, scene.lights, shadows, frameUniforms, camera, size};
        inputs.occupancy = &occupancy;
        gi.update(inputs, profiler);
        const glm::dvec3 e = floorCentreIrradiance(gi.atlas(), mesh,
                                     readAtlas(gi.textures().lit, gi.textures().resolution)) /
                             double(gpuScene.exposure());
        const double expected = kEmitterFormFactor * 2.0;
        if (visibility == ATLAS_VISIBILITY_NONE) {
            // 256 points, about a third on the emitter: 3%.
            EXPECT_NEAR(e.r, expected, 0.03 * expected)
                    << "without visibility the plate is ignored";
        } else {
            EXPECT_LT(e.r, 0.02 * expected) << "the plate hides the emitter from the floor centre";
        }
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

} // namespace
} // namespace gi::test
