// Voxel debug views: marches the camera ray through one cascade level and shows the first
// occupied voxel's albedo, its irradiance as the radiance of a white diffuser (E/pi), or its
// normal (0.5 + 0.5 n). Alpha is 1 where a voxel was hit.
#include "../common/constants.glsl"
#include "../common/frame.glsl"
#include "../common/voxel_cascade.glsl"

#define VIEW_ALBEDO 0
#define VIEW_IRRADIANCE 1
#define VIEW_NORMAL 2

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelAlbedoTexture;
layout(binding = BIND_TEX_VOXEL_IRRADIANCE) uniform sampler3D voxelIrradianceTexture;
layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelNormalTexture;

layout(location = LOC_VOXEL_LEVEL) uniform int levelShown;
layout(location = LOC_VOXEL_DEBUG_VIEW) uniform int viewShown;   // VIEW_*

layout(location = 0) out vec4 outColor;

void main() {
    int level = levelShown;
    int v = voxelResolution();
    vec2 ndc = gl_FragCoord.xy / frame.screen.xy * 2.0 - 1.0;
    vec4 nearPoint = frame.inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 a = nearPoint.xyz / nearPoint.w, b = farPoint.xyz / farPoint.w;
    vec3 dir = normalize(b - a);
    vec3 boxMin = levelOrigin(level), boxMax = boxMin + levelExtent(level);
    vec3 inv = 1.0 / dir;   // IEEE infinities make axis-parallel rays work
    vec3 t0 = (boxMin - a) * inv, t1 = (boxMax - a) * inv;
    float tNear = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), 0.0));
    float tFar = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
    outColor = vec4(0.0);
    if (tNear > tFar) return;
    float step = 0.25 * levelVoxelSize(level);
    int steps = min(int((tFar - tNear) / step) + 1, 8 * v);
    for (int i = 0; i < steps; ++i) {
        vec3 p = a + dir * (tNear + (float(i) + 0.5) * step);
        ivec3 texel = voxelTexel(p, level);
        vec4 albedo = texelFetch(voxelAlbedoTexture, texel, 0);
        if (albedo.a <= 0.0) continue;
        vec3 color = albedo.rgb / albedo.a;
        if (viewShown == VIEW_IRRADIANCE) {
            color = texelFetch(voxelIrradianceTexture, texel, 0).rgb / max(albedo.a, 1e-4) / PI;
        } else if (viewShown == VIEW_NORMAL) {
            color = 0.5 + 0.5 * texelFetch(voxelNormalTexture, texel, 0).xyz;
        }
        outColor = vec4(color, 1.0);
        return;
    }
}
