// Light leaking through a thin wall in texture-atlas GI: two_rooms_thin_wall (scene suite) has
// two closed rooms sharing a wall one finest voxel of the adaptive plan thick (7.7 cm) and a
// point light in one; camera 1 looks into the other, where any indirect light is a leak.
// Without visibility the gather lets every pair of texels that face each other exchange
// light, through the wall too (the thesis); the voxel occupancy must stop it, and rays through
// the scene's triangles (atlas.visibility=bvh) stop all of it.
#include "AtlasGpuTestSupport.h"

#include <cstdio>

namespace gi::test {
namespace {

constexpr int kSize = 48;

double meanIndirect(AtlasFrame& frame, const scene::Camera& camera) {
    frame.render({kSize, kSize}, render::OutputComponent::Indirect, 1, camera);
    const core::Image image = frame.image();
    double sum = 0.0;
    for (const float v : image.rgb) sum += double(v);
    return sum / double(image.rgb.size());
}

TEST_F(AtlasGpuTest, VisibilityKeepsTheDarkRoomDark) {
    const scene::Scene scene = loadTestScene("assets/scene_suite/two_rooms_thin_wall.gltf");
    ASSERT_EQ(scene.cameras.size(), 2u);
    for (const int visibility :
            {ATLAS_VISIBILITY_NONE, ATLAS_VISIBILITY_VOXEL, ATLAS_VISIBILITY_BVH}) {
        Settings settings = atlasSettings(128, 64);
        settings.specular = 0.0f;
        settings.atlas.visibility = visibility;
        AtlasFrame frame(scene, settings);
        const double lit = meanIndirect(frame, scene.cameras[0]);
        const double dark = meanIndirect(frame, scene.cameras[1]);
        const double leak = dark / lit;
        const char* names[] = {"none", "voxel", "bvh"};
        std::printf("atlas.visibility=%s: dark room / lit room indirect light %.5f\n",
                names[visibility], leak);
        ASSERT_GT(lit, 0.0);
        if (visibility == ATLAS_VISIBILITY_VOXEL) {
            EXPECT_LT(leak, 0.01) << "the wall's voxels must block the lit room's senders";
        } else if (visibility == ATLAS_VISIBILITY_BVH) {
            EXPECT_LT(leak, 1e-4) << "every ray from the lit room meets the wall";
        } else {
            EXPECT_GT(leak, 0.05) << "without visibility the wall blocks nothing (the thesis)";
        }
    }
}

} // namespace
} // namespace gi::test
