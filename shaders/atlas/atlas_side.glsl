// Which side of a surface point the camera sees, so a draw from the camera reads the atlas
// layers of that side (AtlasTextures.h: double-sided texels keep their back in the back
// layers). As in the path tracer, the side is the one the interpolated normal faces from the
// camera; single-sided surfaces have only their front.
#ifndef GI_ATLAS_SIDE_GLSL
#define GI_ATLAS_SIDE_GLSL

#include "../common/frame.glsl"

bool cameraSeesBack(vec3 position, vec3 normal, float doubleSided) {
    return doubleSided > 0.5 && dot(normal, frame.cameraPosition.xyz - position) < 0.0;
}

#endif
