// What a texel sends to the next bounce's gather (gi.bounces > 1), one fragment per atlas
// texel: its direct radiance plus the light of the bounce just gathered, rho/pi x E_ind (the
// lit atlas), on each side of a double-sided texel. Coverage stays the direct layer's, so
// the same texels send and receive.
#include "atlas_common.glsl"
#include "../common/constants.glsl"

layout(binding = BIND_TEX_ATLAS_DIRECT) uniform sampler2D atlasDirect;
layout(binding = BIND_TEX_ATLAS_DIRECT_BACK) uniform sampler2D atlasDirectBack;
layout(binding = BIND_TEX_ATLAS_ALBEDO) uniform sampler2D atlasAlbedo;
layout(binding = BIND_TEX_ATLAS_LIT) uniform sampler2D atlasLit;
layout(binding = BIND_TEX_ATLAS_LIT_BACK) uniform sampler2D atlasLitBack;

layout(location = 0) out vec4 outSenders;
layout(location = 1) out vec4 outSendersBack;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 direct = texelFetch(atlasDirect, texel, 0);
    if (direct.a <= 0.0) {
        outSenders = vec4(0.0);
        outSendersBack = vec4(0.0);
        return;
    }
    vec3 reflectance = texelFetch(atlasAlbedo, texel, 0).rgb / PI;
    outSenders = vec4(direct.rgb + reflectance * texelFetch(atlasLit, texel, 0).rgb, direct.a);
    outSendersBack = atlas.dilation.y > 0.5
            ? vec4(texelFetch(atlasDirectBack, texel, 0).rgb +
                           reflectance * texelFetch(atlasLitBack, texel, 0).rgb, direct.a)
            : vec4(0.0);
}
