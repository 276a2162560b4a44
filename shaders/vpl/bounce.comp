// Second-generation VPLs (vpl.bounces=2; SEEDS.md section 4): rays from the first generation's
// VPLs through the voxel occupancy, each stopping on the first voxel surface it meets, where
// it leaves a VPL of the flux that surface reflects.
//
// Ray k starts at parent j = the middle of the k-th of `rays` equal strata over the `parents`
// VPLs, in a direction drawn from the cosine density p(w) = cos(theta) / pi about the
// parent's normal. The estimator: a Lambertian VPL of flux phi sends phi cos(theta) / pi per
// steradian, so the power that reaches the first surface along w, then reflected there with
// albedo rho(w), is
//   P_j = integral over the hemisphere of phi_j cos(theta) / pi rho(w) dw
//       = E_{w ~ p}[ phi_j rho(w) ]:
// the intensity's cos(theta) / pi is the sampling density itself, so one ray's hit carries
// phi_j rho with no further factor. Each parent is drawn for rays / parents of the rays (the
// first generation's VPLs carry equal flux, VplSampler.h, so these equal strata draw them in
// proportion to flux), and each hit stands for parents / rays of a parent's rays:
//   phi_child = phi_j rho(hit) parents / rays,
// whose sum over the rays estimates sum_j P_j, the power of the light's second reflection,
// without bias (a ray leaving the occupancy carries its share out of the scene). The child is
// then a Lambertian VPL like any other: the gather treats both generations alike.
//
// The walk is voxel_visibility.glsl's: voxel by voxel through the finest level containing each
// point, a one-plane voxel stopping only rays that cross its plane, other voxels by coverage.
// Partial coverage stops a ray with that probability (the march's transmittance as a
// stochastic hit), with a fixed random number per ray so the VPLs are the same every time.
#include "../common/constants.glsl"
#include "../common/cosine_direction.glsl"
#include "../common/hash.glsl"
#include "../common/voxel_visibility.glsl"

layout(local_size_x = VPL_BOUNCE_LOCAL_SIZE) in;

layout(std430, binding = BIND_SSBO_VPLS) readonly buffer ParentBlock {
    GpuVpl parentVpls[];
};

layout(std430, binding = BIND_SSBO_VPL_BOUNCES) writeonly buffer HitBlock {
    GpuVpl hitVpls[];
};

layout(location = LOC_VPL_BOUNCE_COUNTS) uniform ivec2 counts;   // parents, rays

// Enough voxel steps to cross the finest level's diagonal and the coarser levels around it.
const int kMaxBounceSteps = 2048;

struct SurfaceHit {
    vec3 position;
    vec3 normal;    // facing where the ray came from
    vec3 albedo;
};

// The R2 sequence (Roberts 2018) in 32-bit fixed point: any stride of it (one interleaved
// subset of the VPLs) is spread as evenly as the whole.
vec2 r2Point(uint k) {
    uvec2 fixedPoint = uvec2(k) * uvec2(0xC13FA9A9u, 0x91E10DA5u) + uvec2(0x80000000u);
    return vec2(fixedPoint >> 8) / 16777216.0;
}

// Where, between p and b inside the voxel, the ray meets the voxel's surface: its plane's
// crossing for a voxel met at its mean plane (voxelMetAtPlane), else the middle of the ray's way
// through the voxel.
vec3 hitPoint(vec4 plane, bool atPlane, vec3 centre, float size, vec3 p, vec3 b) {
    vec3 mid = 0.5 * (p + b);
    if (!atPlane) return mid;
    vec3 n = plane.xyz / length(plane.xyz);
    float approach = dot(n, b - p);
    if (abs(approach) < 1e-6 * size) return mid;
    float s = -voxelPlaneDistance(plane, centre, size, p) * size / approach;
    return mix(p, b, clamp(s, 0.0, 1.0));
}

SurfaceHit surfaceAt(vec4 plane, vec4 albedoCoverage, vec3 position, vec3 dir) {
    SurfaceHit hit;
    hit.position = position;
    float len = length(plane.xyz);
    // A voxel whose surfaces' normals cancel (both sides of a thin wall) faces the ray.
    vec3 n = len > 0.1 ? plane.xyz / len : -dir;
    hit.normal = dot(n, dir) > 0.0 ? -n : n;
    hit.albedo = clamp(albedoCoverage.rgb / max(albedoCoverage.a, 1e-4), 0.0, 1.0);
    return hit;
}

// The first voxel surface along dir from a surface at origin (normal originNormal), `u` in
// (0, 1) choosing where partial coverage stops the ray; false when the ray leaves the cascade.
bool firstSurface(vec3 origin, vec3 originNormal, vec3 dir, float u, out SurfaceHit hit) {
    vec3 a = origin + originNormal * endOffset(origin);
    float t = 0.0;
    float transmittance = 1.0;
    for (int i = 0; i < kMaxBounceSteps; ++i) {
        vec3 p = a + dir * t;
        int level = finestLevel(p);
        // The levels are nested boxes: a ray outside all of them never comes back.
        if (level < 0) return false;
        float size = levelVoxelSize(level);
        ivec3 texel = voxelTexel(p, level);
        vec3 lo = levelOrigin(level) + vec3(texel - ivec3(0, 0, level * voxelResolution())) * size;
        float exit = t + exitDistance(p, dir, lo, size) + 1e-3 * size;
        vec4 albedoCoverage = texelFetch(voxelCoverage, texel, 0);
        float coverage = clamp(albedoCoverage.a, 0.0, 1.0);
        // The first voxel holds the origin's own surface (as in the visibility march).
        if (coverage > 0.0 && i > 0) {
            vec4 plane = texelFetch(voxelPlane, texel, 0);
            vec3 centre = lo + 0.5 * size;
            vec3 b = a + dir * exit;
            bool atPlane = voxelMetAtPlane(plane, level);
            if (!atPlane || segmentCrossesVoxelPlane(plane, centre, size, p, b, kPlaneTolerance)) {
                transmittance *= 1.0 - coverage;
                if (transmittance <= u) {
                    hit = surfaceAt(plane, albedoCoverage,
                            hitPoint(plane, atPlane, centre, size, p, b), dir);
                    return true;
                }
            }
        }
        t = exit;
    }
    return false;
}

void main() {
    int k = int(gl_GlobalInvocationID.x);
    int parents = counts.x, rays = counts.y;
    if (k >= rays) return;
    int j = min(int((float(k) + 0.5) * float(parents) / float(rays)), parents - 1);
    GpuVpl parent = parentVpls[j];
    vec3 n = normalize(parent.normal.xyz);
    vec3 dir = cosineDirection(n, r2Point(uint(k)));
    uint state = hash(uint(k) ^ 0x9E3779B9u);
    float u = max(random01(state), 1e-7);
    GpuVpl child;
    child.position = vec4(0.0);
    child.normal = vec4(0.0);
    child.flux = vec4(0.0);
    SurfaceHit hit;
    if (firstSurface(parent.position.xyz, n, dir, u, hit)) {
        child.position = vec4(hit.position, 1.0);
        child.normal = vec4(hit.normal, 0.0);
        child.flux = vec4(parent.flux.rgb * hit.albedo * (float(parents) / float(rays)), 0.0);
    }
    hitVpls[k] = child;
}
