#include "render/FrameSwitches.h"

#include "gl/Shared.h"

namespace gi::render {

FrameSwitches FrameSwitches::of(const Settings& settings) {
    FrameSwitches switches;
    switches.shadingModel = settings.glossyMaterials() ? SHADING_GLTF
                            : settings.specular > 0.0f ? SHADING_PHONG
                                                       : SHADING_LAMBERT;
    switches.shadowMethod = int(settings.shadow.method);
    switches.shadows = settings.shadow.enabled;
    switches.upsample = !settings.voxel.depthUpsample ? UPSAMPLE_BILINEAR
                        : settings.voxel.planeUpsample ? UPSAMPLE_DEPTH_PLANE
                                                       : UPSAMPLE_DEPTH;
    return switches;
}

std::vector<std::string> FrameSwitches::defines() const {
    return {"FRAME_SHADING_MODEL " + std::to_string(shadingModel),
            "FRAME_SHADOW_METHOD " + std::to_string(shadowMethod),
            std::string("FRAME_SHADOWS ") + (shadows ? "1" : "0"),
            "FRAME_SHADOW_MAPS " + std::to_string(shadowMaps),
            "FRAME_MATERIAL_TEXTURES " + std::to_string(materialTextures),
            "FRAME_LIGHT_KINDS " + std::to_string(lightKinds),
            "FRAME_UPSAMPLE " + std::to_string(upsample)};
}

} // namespace gi::render
