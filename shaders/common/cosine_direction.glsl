// Cosine-distributed directions about a normal, for estimators of irradiance-like integrals
// over the hemisphere (the VPLs' bounce rays, the atlas' sky and near field).
#ifndef GI_COSINE_DIRECTION_GLSL
#define GI_COSINE_DIRECTION_GLSL

#include "constants.glsl"
#include "hash.glsl"

// The direction of u in [0, 1)^2 (u.x: the squared sine of its angle to n, u.y: its turn
// about n), with density cos(theta) / pi over the hemisphere about the unit normal n.
vec3 cosineDirection(vec3 n, vec2 u) {
    // Duff et al. 2017: an orthonormal basis about n without a branch on its direction.
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    float r = sqrt(u.x);
    float phi = 2.0 * PI * u.y;
    return normalize(t * (r * cos(phi)) + bt * (r * sin(phi)) + n * sqrt(max(1.0 - u.x, 0.0)));
}

// Direction i of `count` about n: stratified in the squared sine (stratum i), placed within
// its stratum and turned about n by hashes of `seed`, so each seed gives a new set.
vec3 stratifiedCosineDirection(vec3 n, int i, int count, uint seed) {
    float jitter = float(hash(seed + uint(2 * i)) >> 8) / 16777216.0;
    float turn = float(hash(seed + uint(2 * i + 1)) >> 8) / 16777216.0;
    return cosineDirection(n, vec2((float(i) + jitter) / float(count), turn));
}

#endif
