// Texture-atlas GI against an analytic emitter: the area estimator's irradiance under an
// emitting square matches the point-to-rectangle form factor, and voxel visibility blocks the
// same emitter behind an opaque plate.
#include "AtlasGpuTestSupport.h"

#include "gi/voxel/VoxelizationManager.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace gi::test {
namespace {


// The atlas texel of world point p on triangle t (barycentric in world space).
glm::ivec2 texelOf(
        const atlas::AtlasMesh& mesh, const atlas::Atlas& atlas, std::size_t t, glm::dvec3 p) {
    const auto corner = [&](int k) {
        return glm::dvec3(
                mesh.positions[atlas.vertices[atlas.indices[3 * t + std::size_t(k)]].source]);
    };
    const glm::dvec3 a = corner(0), e1 = corner(1) - a, e2 = corner(2) - a, r = p - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double r1 = glm::dot(r, e1), r2 = glm::dot(r, e2), det = d11 * d22 - d12 * d12;
    const double w1 = (d22 * r1 - d12 * r2) / det, w2 = (d11 * r2 - d12 * r1) / det;
    const glm::dvec2 uv = (1.0 - w1 - w2) * texelPosition(atlas, t, 0) +
            w1 * texelPosition(atlas, t, 1) + w2 * texelPosition(atlas, t, 2);
    return glm::ivec2(glm::floor(uv));
}

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

constexpr double kEmitterFormFactor = 1.7408437; // 4 / sqrt(2) * atan(1 / sqrt(2))

// Mean E_ind over the 3x3 texels around the floor's centre (E is flat there: 0.2% over 1 cm).
glm::dvec3 floorCentreIrradiance(const atlas::Atlas& atlas, const atlas::AtlasMesh& mesh,
        const std::vector<glm::vec4>& lit) {
    const int r = atlas.resolution;
    const glm::ivec2 centre = texelOf(mesh, atlas, 0, glm::dvec3(0.0));
    glm::dvec3 sum(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            sum += glm::dvec3(
                    lit[std::size_t(centre.y + dy) * std::size_t(r) + std::size_t(centre.x + dx)]);
        }
    return sum / 9.0;
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
    const OccupancyVolume occupancy{voxels.textures().albedo, voxels.textures().normal, voxels.uniforms()};

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
