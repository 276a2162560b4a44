// The visibility of a light's direct light at a surface point, for shadow.method:
// SHADOW_METHOD_SHADOWMAP  the light's shadow map (shadows.glsl); an area light is seen from
//                          its centre, so its shadows are hard.
// SHADOW_METHOD_BVH        rays through the scene's BVH (bvh.glsl): one to a punctual light;
//                          for an area light frame.shadowing.y rays to points drawn over its
//                          triangles in proportion to their power, stratified, and the
//                          visibility is the share of the sampled light that arrives,
//                          sum(f V) / sum(f) with f = cos(theta_x) cos(theta_y) / r^2 (the
//                          constant of the sampling density cancels). It scales the exact
//                          unshadowed irradiance (lighting.glsl), so unshadowed and fully
//                          shadowed points are noise-free and only penumbrae carry noise
//                          (the ratio estimator of Heitz et al. 2018, "Combining analytic
//                          direct illumination and stochastic shadows").
// SHADOW_METHOD_LINESPACE  the same rays through the N-tree's line spaces (linespace.glsl),
//                          which keep two leaf voxels off the surfaces at both ends.
// SHADOW_METHOD_VOXEL      one cone per light through the voxel occupancy
//                          (voxel_shadow_cone.glsl), widening with an area light's size;
//                          it stops short of the light by its bounding radius, since the
//                          light's own surface (and what it is mounted on) is voxelized too.
#ifndef GI_DIRECT_VISIBILITY_GLSL
#define GI_DIRECT_VISIBILITY_GLSL

#include "bvh.glsl"
#include "frame.glsl"
#include "hash.glsl"
#include "linespace.glsl"
#include "shadows.glsl"
#include "voxel_shadow_cone.glsl"

float emitterSamplingWeight(GpuEmitter e) {
    vec3 l = e.radiance.rgb;
    float luminance = 0.2126 * l.r + 0.7152 * l.g + 0.0722 * l.b;
    return luminance * length(cross(e.p1.xyz - e.p0.xyz, e.p2.xyz - e.p0.xyz));
}

bool shadowRayOccluded(vec3 origin, vec3 dir, float tMax) {
    if (shadowMethod() == SHADOW_METHOD_LINESPACE) return lineSpaceOccluded(origin, dir, tMax);
    return bvhOccluded(origin, dir, tMax);
}

// How far off a surface shadow rays start (m).
float shadowRayOffset() {
    float offset = frame.shadowing.z;
    if (shadowMethod() != SHADOW_METHOD_LINESPACE) return offset;
    return max(offset, lineSpaceSurfaceClearance());
}

// Where a ray of length r to a point on an emitter stops: just short of it, and for the line
// space the clearance off the emitter's plane (cosY the cosine at the emitter); 0 = nothing
// left to test.
float shadowRayEnd(float r, float cosY) {
    float end = r * (1.0 - 1e-4);
    if (shadowMethod() != SHADOW_METHOD_LINESPACE) return end;
    return max(end - lineSpaceSurfaceClearance() / max(cosY, 0.2), 0.0);
}

float areaLightRayVisibility(GpuLight light, vec3 origin, vec3 n, inout uint state) {
    int first = int(light.spotCone.x), count = int(light.spotCone.y);
    float total = 0.0;
    for (int i = first; i < first + count; ++i) total += emitterSamplingWeight(emitters[i]);
    if (!(total > 0.0)) return 1.0;
    int rays = max(int(frame.shadowing.y), 1);
    float sent = 0.0, arrived = 0.0;
    for (int k = 0; k < rays; ++k) {
        float pick = (float(k) + random01(state)) / float(rays) * total;
        int chosen = first + count - 1;
        for (int i = first; i < first + count; ++i) {
            float weight = emitterSamplingWeight(emitters[i]);
            if (pick < weight) {
                chosen = i;
                break;
            }
            pick -= weight;
        }
        GpuEmitter e = emitters[chosen];
        float u = random01(state), v = random01(state);
        if (u + v > 1.0) {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        vec3 y = e.p0.xyz + u * (e.p1.xyz - e.p0.xyz) + v * (e.p2.xyz - e.p0.xyz);
        vec3 d = y - origin;
        float r2 = dot(d, d);
        if (!(r2 > 0.0)) continue;
        float r = sqrt(r2);
        vec3 w = d / r;
        vec3 front = normalize(cross(e.p1.xyz - e.p0.xyz, e.p2.xyz - e.p0.xyz));
        float cosY = e.radiance.w != 0.0 ? abs(dot(front, w)) : -dot(front, w);
        float cosX = dot(n, w);
        if (cosX <= 0.0 || cosY <= 0.0) continue;
        float f = cosX * cosY / r2;
        sent += f;
        float end = shadowRayEnd(r, cosY);
        if (end <= 0.0 || !shadowRayOccluded(origin, w, end)) arrived += f;
    }
    return sent > 0.0 ? arrived / sent : 1.0;
}

const float kVoxelShadowApertureScale = 0.25;

float voxelShadowCone(GpuLight light, vec3 position, vec3 n) {
    int type = int(light.positionAndType.w);
    if (lightsOfKind(LIGHT_SKY) && type == LIGHT_SKY) return 1.0;
    vec3 toLight;
    float distance;
    lightDirection(light, position, toLight, distance);
    if (lightsOfKind(LIGHT_DIRECTIONAL) && type == LIGHT_DIRECTIONAL) {
        return voxelConeVisibility(position, n, toLight, 1e30, 0.0);
    }
    float radius = type == LIGHT_AREA ? light.spotCone.w : 0.0;
    // A quarter of the light's angular radius: the coarse voxels a wider cone reads spill
    // over the walls beside its path. On the emissive Cornell box (scripts/measure_shadows.py)
    // the full radius gave a relative RMSE of 0.28, half 0.21, a quarter 0.18 (energy 0.93).
    float tanHalfAngle = kVoxelShadowApertureScale * radius / max(distance, 1e-6);
    float end = distance - radius - 2.0 * levelVoxelSize(0);
    return end > 0.0 ? voxelConeVisibility(position, n, toLight, end, min(tanHalfAngle, 1.0)) : 1.0;
}

// `state`: the caller's random state (e.g. seeded from the pixel), advanced here.
float directVisibility(int lightIndex, vec3 position, vec3 n, float distanceToLight,
        inout uint state) {
    if (!shadowsApplied()) return 1.0;
    if (shadowMethod() == SHADOW_METHOD_SHADOWMAP) {
        return shadowVisibility(lightIndex, position, n, distanceToLight);
    }
    GpuLight light = lights[lightIndex];
    int type = int(light.positionAndType.w);
    if (shadowMethod() == SHADOW_METHOD_VOXEL) return voxelShadowCone(light, position, n);
    vec3 origin = position + n * shadowRayOffset();
    if (lightsOfKind(LIGHT_AREA) && type == LIGHT_AREA) {
        return areaLightRayVisibility(light, origin, n, state);
    }
    if (lightsOfKind(LIGHT_SKY) && type == LIGHT_SKY) return 1.0;
    vec3 toLight;
    float distance;
    lightDirection(light, origin, toLight, distance);
    float tMax = type == LIGHT_DIRECTIONAL ? 1e30 : distance * (1.0 - 1e-4);
    return shadowRayOccluded(origin, toLight, tMax) ? 0.0 : 1.0;
}

#endif
