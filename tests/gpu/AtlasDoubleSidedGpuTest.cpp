// Double-sided materials in texture-atlas GI, as the path tracer shades them: each side of a
// double-sided surface is lit, sends and receives on its own side, and both sides emit. A
// closed box of double-sided walls then looks exactly like one of single-sided walls facing
// in, and a double-sided plate lit from above sends nothing below it.
#include "AtlasGpuTestSupport.h"

#include "reference/ReferenceRenderer.h"

#include <cstdio>

namespace gi::test {
namespace {

constexpr int kSize = 64;

double imageSum(const core::Image& image) {
    double sum = 0.0;
    for (const float v : image.rgb) sum += double(v);
    return sum;
}

scene::Scene loadSuiteScene(const char* name) {
    return loadTestScene(std::string("assets/scene_suite/") + name + ".gltf");
}

// The atlas' indirect light (area estimator, no visibility) from camera 0, summed over the
// image.
double atlasIndirectSum(const scene::Scene& scene) {
    Settings settings = atlasSettings(128, 256);
    settings.specular = 0.0f;
    settings.atlas.progressive = false;
    settings.atlas.rotate = false;
    AtlasFrame frame(scene, settings);
    frame.render({kSize, kSize}, render::OutputComponent::Indirect);
    return imageSum(frame.image());
}

double referenceIndirectSum(const scene::Scene& scene) {
    ReferenceSettings settings;
    settings.spp = 32;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    return imageSum(reference::renderReference(scene, camera, kSize, kSize, settings).indirect);
}

// cornell_double_sided is cornell_classic with every material double-sided (and TEXCOORD_0):
// the path tracer shades the two alike, so the atlas must too. Before each side had its own
// layers, a double-sided receiver kept the mean of both sides' irradiance and the box's
// indirect light fell to 0.67 of the classic box's.
TEST_F(AtlasGpuTest, DoubleSidedCornellBoxMatchesTheClassicOne) {
    const scene::Scene classic = loadSuiteScene("cornell_classic");
    const scene::Scene doubleSided = loadSuiteScene("cornell_double_sided");
    const double reference = referenceIndirectSum(doubleSided) / referenceIndirectSum(classic);
    const double atlas = atlasIndirectSum(doubleSided) / atlasIndirectSum(classic);
    std::printf("indirect light, double-sided / classic box: reference %.4f, atlas %.4f\n",
            reference, atlas);
    EXPECT_NEAR(reference, 1.0, 0.02) << "the path tracer ignores doubleSided in a closed box";
    EXPECT_NEAR(atlas, 1.0, 0.02);
}

// A grey floor square and an equal double-sided square 0.5 m above it, facing up (away from
// the floor): emitting (L, black) without lights, or grey under a point light 0.5 m above it.
scene::Scene doubleSidedSquareOverFloor(bool emitting) {
    scene::Scene scene;
    scene::Material grey, square;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    square.baseColorFactor = emitting ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : grey.baseColorFactor;
    square.emissiveFactor = emitting ? glm::vec3(2.0f, 1.0f, 0.5f) : glm::vec3(0.0f);
    square.doubleSided = true;
    scene.materials = {grey, square};
    addPrimitive(scene, horizontalSquare(0.5f, 0.0f));
    scene::Primitive top = horizontalSquare(0.5f, 0.5f);
    top.material = 1;
    addPrimitive(scene, top);
    if (!emitting) {
        scene::Light light;
        light.position = glm::vec3(0.0f, 1.0f, 0.0f);
        scene.lights.push_back(light);
    }
    scene.cameras.push_back(lookAtCamera({0.0f, 0.25f, 0.4f}, {0.0f, 0.25f, 0.0f}, 50.0f));
    return scene;
}

glm::dvec3 atlasFloorCentreIrradiance(const scene::Scene& scene) {
    Settings settings = atlasSettings(256, 1024);
    settings.atlas.progressive = false;
    settings.atlas.rotate = false;
    AtlasFrame frame(scene, settings);
    frame.render({32, 32});
    return floorCentreIrradiance(frame.gi().atlas(), atlas::flattenScene(scene), frame.lit());
}

// Both sides emit: the floor under the square's back gets the form factor's irradiance.
TEST_F(AtlasGpuTest, DoubleSidedEmitterSendsFromItsBack) {
    const glm::dvec3 e = atlasFloorCentreIrradiance(doubleSidedSquareOverFloor(true));
    const glm::dvec3 expected = kEmitterFormFactor * glm::dvec3(2.0, 1.0, 0.5);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], expected[c], 0.02 * expected[c]) << c;
}

// The light lights the square's top only; its unlit back sends nothing to the floor. (With one
// value per texel the floor got the top's radiance: 1.7408 x 0.5 / pi x 4 W/m^2 ~ 1.1 W/m^2.)
TEST_F(AtlasGpuTest, DoubleSidedPlateLitFromAboveSendsNothingBelow) {
    const glm::dvec3 e = atlasFloorCentreIrradiance(doubleSidedSquareOverFloor(false));
    std::printf("floor centre under the lit plate: E_ind %.3g W/m^2\n", e.r);
    EXPECT_LT(e.r, 1e-3);
}

} // namespace
} // namespace gi::test
