// Which side of a double-sided surface is lit, as the path tracer decides it: the shading
// normal is turned towards the viewer by its own sign, whatever the triangle's winding says,
// and a light lights the side it is in front of. A quad whose normals point against its
// winding is where a winding-based rule (gl_FrontFacing) and the path tracer disagree.
#include "GpuTest.h"
#include "TestScenes.h"

#include "reference/ReferenceRenderer.h"
#include "render/FrameRenderer.h"

#include <glm/gtc/constants.hpp>

namespace gi::test {
namespace {

constexpr int kSize = 32;
constexpr float kAlbedo = 0.5f;

// A 1 m double-sided quad in the plane z = 0, wound counter-clockwise seen from +z (the camera
// at z = 2 sees its winding's front), its normals pointing to -z, away from the camera; a
// point light 1 m in front of the quad's centre, on the camera's side or behind the quad.
scene::Scene reversedQuad(bool lightOnCameraSide) {
    scene::Scene scene;
    scene::Material material;
    material.baseColorFactor = glm::vec4(kAlbedo, kAlbedo, kAlbedo, 1.0f);
    material.doubleSided = true;
    scene.materials = {material};
    scene::Primitive quad;
    quad.positions = {{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f},
            {-0.5f, 0.5f, 0.0f}};
    quad.normals.assign(4, glm::vec3(0.0f, 0.0f, -1.0f));
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    for (const glm::vec3& v : quad.positions) quad.localBounds.extend(v);
    addPrimitive(scene, quad);
    scene::Light light;
    light.position = glm::vec3(0.0f, 0.0f, lightOnCameraSide ? 1.0f : -1.0f);
    scene.lights.push_back(light);
    scene.cameras.push_back(lookAtCamera({0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 20.0f));
    return scene;
}

glm::vec3 directCentre(const scene::Scene& scene) {
    gl::ShaderLibrary shaders;
    render::FrameRenderer renderer;
    Settings settings;
    settings.specular = 0.0f;
    std::string error;
    EXPECT_TRUE(renderer.init(scene, settings, shaders, error)) << error;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    gl::GpuProfiler profiler;
    renderer.render(camera, {kSize, kSize}, render::OutputComponent::Direct, profiler);
    profiler.flush();
    return renderer.readback().at(kSize / 2, kSize / 2);
}

glm::vec3 referenceCentre(const scene::Scene& scene) {
    ReferenceSettings settings;
    settings.spp = 4;
    const scene::CameraView camera = scene::cameraFromScene(scene.cameras[0], 1.0f, scene.bounds);
    return reference::renderReference(scene, camera, kSize, kSize, settings)
            .direct.at(kSize / 2, kSize / 2);
}

class DoubleSidedGpuTest : public GpuTest {};

// The light on the camera's side lights the side the camera sees: rho/pi x I / 1 m^2.
TEST_F(DoubleSidedGpuTest, ReversedNormalsAreLitOnTheViewersSide) {
    const scene::Scene scene = reversedQuad(true);
    const float expected = kAlbedo / glm::pi<float>();
    EXPECT_NEAR(referenceCentre(scene).r, expected, 0.01f * expected);
    EXPECT_NEAR(directCentre(scene).r, expected, 0.01f * expected);
}

// The light behind the quad lights only the side the camera does not see.
TEST_F(DoubleSidedGpuTest, ReversedNormalsAreDarkWhenLitFromBehind) {
    const scene::Scene scene = reversedQuad(false);
    EXPECT_EQ(referenceCentre(scene).r, 0.0f);
    EXPECT_LT(directCentre(scene).r, 1e-6f);
}

} // namespace
} // namespace gi::test
