// The glTF 2.0 metallic-roughness BRDF on the GPU (material.model=gltf), the same as the path
// tracer's (src/reference/GltfBrdf.h, which gives the formulas and sources):
//   f(v, l) = (1 - F) c_diff / pi + F D Vis,  F0 = mix(0.04, baseColor, metallic),
// GGX D, height-correlated Smith Vis = G2 / (4 n.l n.v), alpha = roughness^2.
// For light that arrives as irradiance or along a cone rather than from one direction:
// - the diffuse weight under uniform light, c_diff (1 - F0) (1 - K(n.v)), and
// - the split-sum specular albedo E_spec = F0 A + B (Karis 2013), both tabulated by
//   scripts/make_env_brdf_table.py for this G;
// - the cone's direction, the lobe's dominant direction (Lagarde and de Rousiers 2014,
//   "Moving Frostbite to PBR", 4.9.3), its half-angle and the share of the lobe it stands
//   for (specularCone).
#ifndef GI_BRDF_GLSL
#define GI_BRDF_GLSL

#include "constants.glsl"
#include "env_brdf_table.glsl"

const float kDielectricF0 = 0.04;   // glTF: index of refraction 1.5
const float kMinAlpha = 1e-3;       // as GltfBrdf.h: roughness 0 stays a finite lobe

struct GltfSurface {
    vec3 diffuse;   // c_diff
    vec3 f0;
    float roughness;
    float alpha;
};

GltfSurface gltfSurface(vec3 baseColor, float metallic, float roughness) {
    GltfSurface s;
    float m = clamp(metallic, 0.0, 1.0);
    s.roughness = clamp(roughness, 0.0, 1.0);
    s.diffuse = baseColor * (1.0 - m);
    s.f0 = mix(vec3(kDielectricF0), baseColor, m);
    s.alpha = max(s.roughness * s.roughness, kMinAlpha);
    return s;
}

vec3 schlickFresnel(vec3 f0, float cosine) {
    float m = 1.0 - clamp(cosine, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

float ggxDistribution(float alpha, float cosH) {
    float a2 = alpha * alpha;
    float d = cosH * cosH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

float smithVisibility(float alpha, float cosL, float cosV) {
    float a2 = alpha * alpha;
    float sum = cosL * sqrt(cosV * cosV * (1.0 - a2) + a2) +
                cosV * sqrt(cosL * cosL * (1.0 - a2) + a2);
    return sum > 0.0 ? 0.5 / sum : 0.0;
}

// f(v, l), 0 unless both lie on n's side.
vec3 gltfBrdf(GltfSurface s, vec3 n, vec3 v, vec3 l) {
    float cosV = dot(n, v), cosL = dot(n, l);
    if (cosV <= 0.0 || cosL <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    vec3 fresnel = schlickFresnel(s.f0, dot(v, h));
    float specular = ggxDistribution(s.alpha, max(dot(n, h), 0.0)) *
                     smithVisibility(s.alpha, cosL, cosV);
    return (1.0 - fresnel) * s.diffuse / PI + fresnel * specular;
}

// Bilinear lookup of the tables at (roughness, n.v), both in [0, 1].
vec2 envBrdfAB(float roughness, float cosV) {
    vec2 p = clamp(vec2(roughness, cosV), 0.0, 1.0) * float(kEnvBrdfSteps - 1);
    ivec2 i = min(ivec2(p), ivec2(kEnvBrdfSteps - 2));
    vec2 f = p - vec2(i);
    int row = i.x * kEnvBrdfSteps + i.y;
    vec2 low = mix(kEnvBrdf[row], kEnvBrdf[row + 1], f.y);
    vec2 high = mix(kEnvBrdf[row + kEnvBrdfSteps], kEnvBrdf[row + kEnvBrdfSteps + 1], f.y);
    return mix(low, high, f.x);
}

vec3 specularAlbedo(GltfSurface s, float cosV) {
    vec2 ab = envBrdfAB(s.roughness, cosV);
    return s.f0 * ab.x + ab.y;
}

// What c_diff / pi is multiplied by under uniform incident light: the diffuse term's
// Fresnel loss, (1 - F0) (1 - K(n.v)).
vec3 diffuseIndirectWeight(GltfSurface s, float cosV) {
    float p = clamp(cosV, 0.0, 1.0) * float(kEnvBrdfSteps - 1);
    int i = min(int(p), kEnvBrdfSteps - 2);
    float k = mix(kDiffuseFresnel[i], kDiffuseFresnel[i + 1], p - float(i));
    return s.diffuse * (1.0 - s.f0) * (1.0 - k);
}

// What the surface reflects, into the whole hemisphere, of light arriving at cosine cosL to its
// normal: by reciprocity the directional albedo seen from there, diffuse and specular lobes
// together (a metal's highlight and a dielectric's sheen leave the surface as light too, and
// the Fresnel factor takes away from the diffuse part; reflectance.glsl).
vec3 directionalAlbedo(GltfSurface s, float cosL) {
    return diffuseIndirectWeight(s, cosL) + specularAlbedo(s, cosL);
}

// directionalAlbedo under uniform light (the white-sky albedo): the share of irradiance from
// every direction alike the surface reflects.
vec3 uniformLightAlbedo(GltfSurface s) {
    float p = s.roughness * float(kEnvBrdfSteps - 1);
    int i = min(int(p), kEnvBrdfSteps - 2);
    vec2 ab = mix(kEnvBrdfUniform[i], kEnvBrdfUniform[i + 1], p - float(i));
    return s.diffuse * (1.0 - s.f0) * (1.0 - kDiffuseFresnelUniform) + s.f0 * ab.x + ab.y;
}

// Where the specular lobe of a rough surface points: between the mirror direction and the
// normal, as G and the lobe's foreshortening pull it (Frostbite's fit).
vec3 specularDominantDirection(GltfSurface s, vec3 n, vec3 v) {
    vec3 r = reflect(-v, n);
    float a = s.alpha;
    float lerpFactor = (1.0 - a) * (sqrt(1.0 - a) + a);
    return normalize(mix(n, r, lerpFactor));
}

// The specular lobe's core, which one cone stands for. GGX has long tails: the fraction of
// its (projected) microfacet normals within theta_h of the normal is
// tan^2 / (alpha^2 + tan^2), so the lobe's half-maximum (tan = 0.64 alpha) holds only 29% of
// them. The cone takes the half vectors within tan(theta_h) = 3 alpha, 90% of them, as wide as
// a reflected direction turns for them: 2 theta_h, at most 60 degrees (a rough lobe's cone
// then holds fewer: 25% at roughness 1). What the cone leaves out is spread widely and takes
// the cosine-weighted mean radiance the diffuse cones found, E_ind / pi. The tails are not
// spread evenly over the hemisphere: they lie around the mirror direction, and a metal facing
// an open side of a room sees that opening in them too, so the cone takes as much of the lobe
// as its width allows (results-glossy.md measures the choice).
struct SpecularCone {
    float tanHalfAngle;
    float share;   // of the lobe's microfacet normals
};

const float kSpecularConeTargetShare = 0.9;

SpecularCone specularCone(GltfSurface s) {
    float target = kSpecularConeTargetShare;
    float halfVector = min(atan(s.alpha * sqrt(target / (1.0 - target))), radians(30.0));
    float t = tan(halfVector);
    SpecularCone cone;
    cone.tanHalfAngle = tan(2.0 * halfVector);
    cone.share = t * t / (s.alpha * s.alpha + t * t);
    return cone;
}

#endif
