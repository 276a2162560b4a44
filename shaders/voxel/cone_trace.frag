// Cone tracing (thesis 4.2.5, 4.3.3.4, Listing 4.5): 9 cones per pixel, one along the normal
// and eight rotated by 50 degrees around it, each a volume ray-march whose step and cascade
// level grow with the cone's diameter; front-to-back accumulation until the cone is opaque
// or leaves the volume. Samples of voxels facing away from the cone add no light (they
// still occlude) and a voxel is read at most once per cone.
//
// Calibration (so the output is E_ind in W/m^2, DESIGN.md): a voxel's premultiplied
// outgoing radiance is albedo/pi * E (E premultiplied by coverage through propagation);
// a cone returns the composited radiance L_i seen along it (no sky: an escaping cone adds
// nothing); E_ind = pi * sum_i w_i L_i, where w_i is the fraction of the cosine-weighted
// hemisphere the cone stands for (central cap: sin^2(theta_b), each ring cone
// cos^2(theta_b)/8, theta_b halfway between the central axis and the ring). The thesis'
// weights (cos theta_i, normalised by their sum) differ from these by under 10%.
// Opacity uses the step-length correction alpha' = 1 - (1 - alpha)^(step / voxel size).
#include "../common/frame.glsl"
#include "../common/material.glsl"
#include "voxel_common.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelAlbedoTexture;
layout(binding = BIND_TEX_VOXEL_IRRADIANCE) uniform sampler3D voxelIrradianceTexture;
layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelNormalTexture;

layout(location = LOC_DRAW_MATERIAL) uniform int drawMaterial;

in VertexData {
    vec3 position;
    vec3 normal;
    vec2 texcoord0;
    vec2 texcoord1;
    vec4 color;
} vin;

layout(location = 0) out vec4 outIndirect;

const float PI = 3.14159265358979;
const int kMaxSteps = 512;

struct VoxelSample {
    vec4 albedo;       // rgb = albedo, a = coverage
    vec3 irradiance;   // premultiplied by coverage
    vec3 normal;
};

VoxelSample readLevel(vec3 p, int level) {
    vec3 tc = voxelTexcoord(p, level);
    VoxelSample s;
    s.albedo = texture(voxelAlbedoTexture, tc);
    s.irradiance = texture(voxelIrradianceTexture, tc).rgb;
    s.normal = texture(voxelNormalTexture, tc).xyz;
    return s;
}

vec3 traceCone(vec3 origin, vec3 dir, float maxDistance) {
    float tanHalf = voxel.trace.x;
    float finest = levelVoxelSize(0);
    int startLevel = max(finestLevel(origin), 0);
    float dist = levelVoxelSize(startLevel);
    vec3 radiance = vec3(0.0);
    float opacity = 0.0;
    ivec4 lastTexel = ivec4(-1);
    for (int step = 0; step < kMaxSteps && dist < maxDistance && opacity < 0.99; ++step) {
        vec3 p = origin + dir * dist;
        int available = finestLevel(p);
        if (available < 0) break;
        float diameter = max(2.0 * tanHalf * dist, finest);
        float lod = clamp(log2(diameter / finest), float(available), float(voxelLevels() - 1));
        int level = int(floor(lod));
        float blend = lod - float(level);
        // Once the cone is wider than the coarsest level's voxels, steps stay one such voxel
        // long: longer steps would jump over walls the level resolves.
        float stepLength = max(min(diameter, levelVoxelSize(level + (blend > 0.0 ? 1 : 0))) *
                voxel.trace.z, 0.25 * finest);
        ivec4 texel = ivec4(voxelTexel(p, level), level);
        if (texel == lastTexel) {
            dist += stepLength;
            continue;
        }
        lastTexel = texel;
        VoxelSample s = readLevel(p, level);
        float voxelSize = levelVoxelSize(level);
        if (blend > 0.0 && level + 1 < voxelLevels()) {
            VoxelSample t = readLevel(p, level + 1);
            s.albedo = mix(s.albedo, t.albedo, blend);
            s.irradiance = mix(s.irradiance, t.irradiance, blend);
            s.normal = mix(s.normal, t.normal, blend);
            voxelSize = mix(voxelSize, levelVoxelSize(level + 1), blend);
        }
        float alpha = clamp(s.albedo.a, 0.0, 1.0);
        if (alpha > 0.0) {
            float corrected = 1.0 - pow(1.0 - min(alpha, 0.9999), stepLength / voxelSize);
            vec3 light = s.albedo.rgb / PI * s.irradiance * (corrected / alpha);
            // A voxel facing away from the cone is skipped, as in the thesis: its surface
            // sends no light this way, and its occlusion would mostly be the cone's own
            // surface seen from behind (the voxel layer the cone starts in).
            if (dot(s.normal, dir) > 0.0) {
                dist += stepLength;
                continue;
            }
            if (voxel.trace.w != 0.0) light /= 1.0 + dist * dist; // the thesis' falloff
            radiance += (1.0 - opacity) * light;
            opacity += (1.0 - opacity) * corrected;
        }
        dist += stepLength;
    }
    return radiance;
}

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;
    float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
    int level = finestLevel(vin.position);
    if (level < 0) {
        outIndirect = vec4(0.0, 0.0, 0.0, viewDepth);
        return;
    }
    vec3 n = normalize(vin.normal);
    if (!gl_FrontFacing) n = -n;
    // Leave the surface's own voxel before the first sample.
    vec3 origin = vin.position + n * levelVoxelSize(level);
    float maxDistance = voxel.trace.y;

    vec3 t = normalize(abs(n.y) < 0.99 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(n, t);
    float cosRing = voxel.traceWeights.z, sinRing = voxel.traceWeights.w;
    // With voxel.jitter the ring turns by a 4x4 ordered-dither fraction of its 45-degree
    // spacing, so neighbouring pixels sample 16 different ring directions; the filter pass
    // averages them back into a smooth result.
    float ringTurn = 0.0;
    if (voxel.smoothing.y != 0.0) {
        const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0,
                                          3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
        ivec2 cell = ivec2(gl_FragCoord.xy) & 3;
        ringTurn = (bayer[cell.y * 4 + cell.x] + 0.5) / 16.0 * (PI / 4.0);
    }
    vec3 e = voxel.traceWeights.x * traceCone(origin, n, maxDistance);
    for (int i = 0; i < 8; ++i) {
        float phi = float(i) * (PI / 4.0) + ringTurn;
        vec3 dir = cosRing * n + sinRing * (cos(phi) * t + sin(phi) * b);
        e += voxel.traceWeights.y * traceCone(origin, dir, maxDistance);
    }
    outIndirect = vec4(PI * e, viewDepth);
}
