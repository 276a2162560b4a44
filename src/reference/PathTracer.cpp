#include "reference/PathTracer.h"

#include "reference/GltfBrdf.h"
#include "reference/LightSampling.h"
#include "reference/SamplingMath.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::reference {
namespace {

// A shadow ray towards a point or spot light stops this fraction short of the light, so a
// light placed exactly on a surface is not shadowed by it.
constexpr float kShadowRayShortening = 1e-4f;

} // namespace

PathTracer::PathTracer(const EmbreeState& state, const std::vector<scene::Light>& lights,
        const scene::CameraView& camera, int width, int height, int bounces, bool glossy)
    : mState(state), mLights(lights), mAreaLights(state, lights), mWidth(width),
      mHeight(height), mBounces(bounces), mGlossy(glossy) {
    const glm::dmat4 clipToWorld =
            glm::inverse(glm::dmat4(camera.projection) * glm::dmat4(camera.view));
    mNear[0] = clipToWorld * glm::dvec4(0.0, 0.0, -1.0, 1.0);
    mFar[0] = clipToWorld * glm::dvec4(0.0, 0.0, 1.0, 1.0);
    for (int axis = 0; axis < 2; ++axis) {
        glm::dvec4 unit(0.0);
        unit[axis] = 1.0;
        mNear[axis + 1] = mFar[axis + 1] = clipToWorld * unit;
    }
    for (const scene::Light& light : lights) {
        mEmissionPdf.push_back(emissionPdf(light));
        const glm::vec3 radiance = light.color * light.intensity;
        if (light.type == scene::LightType::Sky && usableLight(light, radiance)) mSky += radiance;
    }
    const bool emissive = std::any_of(state.materials.begin(), state.materials.end(),
            [](const ShadingMaterial& m) { return maxComponent(m.emissiveFactor) > 0.0f; });
    mClosingRay = emissive || maxComponent(mSky) > 0.0f;
}

// One path through continuous image coordinates (x, y), x in [0, width) left to right,
// y in [0, height) top to bottom. u[0..1]: the camera hit's cosine ray, u[2..3]: the first
// light's emission direction; everything else comes from `rng`. Numbers for area lights and
// the closing ray are drawn only in scenes that have them, so other scenes keep their random
// streams. `lightVertices` is scratch space reused between calls.
PathSample PathTracer::trace(float x, float y, const float u[4], Pcg32& rng,
        std::vector<LightVertex>& lightVertices, RayCounts& counts) const {
    PathSample result;
    RTCIntersectContext coherent, incoherent;
    rtcInitIntersectContext(&coherent);
    coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcInitIntersectContext(&incoherent);
    RTCRayHit rayHit = cameraRay(x, y);
    ++counts.primary;
    rtcIntersect1(mState.rtcScene, &coherent, &rayHit);
    Surface surface;
    if (!interact(rayHit, surface)) return result;
    result.hit = true;
    result.direct = surface.emission;
    if (mBounces > 0) sampleLightVertices(u + 2, rng, lightVertices, incoherent, counts);

    glm::vec3 throughput(1.0f);
    float pdfArea = -1.0f;   // this vertex's density under cosine sampling from the last one
    for (int vertex = 0;; ++vertex) {
        glm::vec3& term = vertex == 0 ? result.direct : result.indirect;
        const bool last = vertex == mBounces;
        term += throughput * directLight(surface, pdfArea, incoherent, counts);
        if (!mAreaLights.empty()) {
            const float u1 = rng.nextFloat(), u2 = rng.nextFloat();
            term += throughput * areaLight(surface, u1, u2, incoherent, counts);
        }
        const bool dark = mGlossy ? !reflects(surface) || maxComponent(throughput) <= 0.0f
                                  : maxComponent(throughput * surface.albedo) <= 0.0f;
        if ((last && !mClosingRay) || dark) break;
        if (!last) {
            result.indirect += throughput * connect(surface, lightVertices, incoherent, counts);
        }
        const float u1 = vertex == 0 ? u[0] : rng.nextFloat();
        const float u2 = vertex == 0 ? u[1] : rng.nextFloat();
        glm::vec3 direction;
        if (mGlossy) {
            const float lobe[3] = {rng.nextFloat(), u1, u2};
            if (!sampleBrdf(surface.brdf, surface.shadingNormal, surface.toViewer, lobe,
                        direction)) {
                break;
            }
        } else {
            throughput *= surface.albedo;
            direction = sampleCosineHemisphere(surface.shadingNormal, u1, u2);
        }
        const float cosSampled = glm::dot(direction, surface.shadingNormal);
        if (glm::dot(direction, surface.geometricNormal) <= 0.0f || cosSampled <= 0.0f) break;
        const float pdfBounce = bouncePdf(surface, direction, cosSampled);
        if (mGlossy) {
            if (!(pdfBounce > 0.0f)) break;
            throughput *= glossyBrdf(surface, direction) * (cosSampled / pdfBounce);
        }
        const glm::vec3 origin = offsetOrigin(surface);
        rayHit = ray(origin, direction, std::numeric_limits<float>::infinity());
        ++counts.bounce;
        rtcIntersect1(mState.rtcScene, &incoherent, &rayHit);
        if (!interact(rayHit, surface)) {
            term += throughput * mSky;
            break;
        }
        const glm::vec3 step = surface.position - origin;
        const float distance2 = glm::dot(step, step);
        if (maxComponent(surface.emission) > 0.0f) {
            term += throughput * surface.emission *
                    bounceEmissionWeight(surface, pdfBounce, distance2, direction);
        }
        if (last) break;
        pdfArea = pdfBounce * std::abs(glm::dot(surface.geometricNormal, direction)) /
                std::max(distance2, std::numeric_limits<float>::min());
    }
    return result;
}

RTCRayHit PathTracer::ray(const glm::vec3& origin, const glm::vec3& direction, float tfar) {
    return makeRayHit(origin, direction, 0.0f, tfar);
}

// The ray through a point of the image, from the near plane to the far plane, exactly as
// the raster passes clip it.
RTCRayHit PathTracer::cameraRay(float x, float y) const {
    const double ndcX = 2.0 * double(x) / double(mWidth) - 1.0;
    const double ndcY = 1.0 - 2.0 * double(y) / double(mHeight);
    const glm::dvec4 nearH = mNear[0] + ndcX * mNear[1] + ndcY * mNear[2];
    const glm::dvec4 farH = mFar[0] + ndcX * mFar[1] + ndcY * mFar[2];
    const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
    const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
    const glm::dvec3 span = farP - nearP;
    const double length = glm::length(span);
    return ray(glm::vec3(nearP), glm::vec3(span / length), float(length));
}

glm::vec3 PathTracer::offsetOrigin(const Surface& surface) {
    return surface.position + surface.offset * surface.geometricNormal;
}

bool PathTracer::interact(const RTCRayHit& rayHit, Surface& surface) const {
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    const std::uint32_t triangle = mState.firstTriangle[rayHit.hit.geomID] + rayHit.hit.primID;
    const glm::uvec3 t = mState.triangles[triangle];
    const float u = rayHit.hit.u, v = rayHit.hit.v, w = 1.0f - u - v;
    const glm::vec3& p0 = mState.positions[t.x];
    const glm::vec3& p1 = mState.positions[t.y];
    const glm::vec3& p2 = mState.positions[t.z];
    const glm::vec3 incoming(-rayHit.ray.dir_x, -rayHit.ray.dir_y, -rayHit.ray.dir_z);
    const TriangleInfo& info = mState.triangleInfo[triangle];

    surface.position = w * p0 + u * p1 + v * p2;
    glm::vec3 ng = info.normal == glm::vec3(0.0f) ? incoming : info.normal;
    if (glm::dot(ng, incoming) < 0.0f) ng = -ng;
    glm::vec3 ns = ng;
    if (info.flags & kSmoothNormals) {
        ns = w * mState.normals[t.x] + u * mState.normals[t.y] + v * mState.normals[t.z];
        const float nsLength = glm::length(ns);
        ns = nsLength > 0.0f && std::isfinite(nsLength) ? ns / nsLength : ng;
        if (glm::dot(ns, incoming) < 0.0f) ns = -ns;
    }
    surface.geometricNormal = ng;
    surface.shadingNormal = ns;
    surface.offset = info.offset;

    surface.triangle = triangle;
    surface.albedo = glm::vec3(mState.baseColor(triangle, u, v));
    surface.toViewer = incoming;
    if (mGlossy) {
        const ShadingMaterial& m = mState.materials[info.material];
        surface.brdf = makeGltfBrdf(surface.albedo, m.metallic, m.roughness);
    }
    surface.emission = mState.emitsTowards(triangle, incoming) ? mState.emission(triangle, u, v)
                                                              : glm::vec3(0.0f);
    return true;
}

bool PathTracer::occluded(const glm::vec3& origin, const glm::vec3& direction, float tfar,
        RTCIntersectContext& context, RayCounts& counts) const {
    RTCRay shadow = ray(origin, direction, tfar).ray;
    ++counts.shadow;
    rtcOccluded1(mState.rtcScene, &context, &shadow);
    return shadow.tfar < 0.0f;
}

// Outgoing radiance rho/pi x sum over lights of (colour x intensity x E) x visibility, with
// E per DESIGN.md "Radiometric conventions". With pdfArea >= 0 (the density of this vertex
// under cosine sampling from the previous one), contributions of lights that also have
// light vertices carry the MIS weight pA / (pA + pB); with pdfArea < 0 (camera hit) none.
glm::vec3 PathTracer::directLight(const Surface& surface, float pdfArea,
        RTCIntersectContext& context, RayCounts& counts) const {
    if (!reflects(surface)) return glm::vec3(0.0f);
    glm::vec3 sum(0.0f);
    const glm::vec3 origin = offsetOrigin(surface);
    for (std::size_t i = 0; i < mLights.size(); ++i) {
        const scene::Light& light = mLights[i];
        const glm::vec3 radiant = light.color * light.intensity;
        if (!isPunctual(light.type) || !usableLight(light, radiant)) continue;
        glm::vec3 wi;
        float distance = 0.0f, factor = 0.0f;
        if (!lightGeometry(light, surface.position, wi, distance, factor)) continue;
        const float cosTheta = glm::dot(surface.shadingNormal, wi);
        const float cosGeometric = glm::dot(surface.geometricNormal, wi);
        if (cosTheta <= 0.0f || cosGeometric <= 0.0f) continue;
        float tfar = distance;
        if (std::isfinite(distance)) {
            tfar = glm::length(light.position - origin) * (1.0f - kShadowRayShortening);
        }
        if (occluded(origin, wi, tfar, context, counts)) continue;
        float weight = 1.0f;
        if (pdfArea >= 0.0f && mEmissionPdf[i] > 0.0f) {
            const float pdfLight = mEmissionPdf[i] * cosGeometric / (distance * distance);
            weight = pdfArea / (pdfArea + pdfLight);
        }
        sum += glossyBrdf(surface, wi) * radiant * (factor * cosTheta * weight);
    }
    return mGlossy ? sum : surface.albedo * glm::one_over_pi<float>() * sum;
}

// Area lights at x by one point sampled from them (AreaLightSampling.h) and a visibility ray
// that stops just in front of it: rho/pi Le cos_x / pL x weight, pL the solid-angle density.
// A point on scene geometry could also be found by x's cosine ray (always cast when the scene
// has emissive surfaces): then the weight is pL / (pL + pB), otherwise 1.
glm::vec3 PathTracer::areaLight(const Surface& x, float u1, float u2,
        RTCIntersectContext& context, RayCounts& counts) const {
    EmitterSample y;
    if (!reflects(x) || !mAreaLights.sample(u1, u2, y)) return glm::vec3(0.0f);
    const glm::vec3 toY = y.position - x.position;
    const float distance2 = glm::dot(toY, toY);
    if (!(distance2 > 0.0f) || !std::isfinite(distance2)) return glm::vec3(0.0f);
    const glm::vec3 wi = toY / std::sqrt(distance2);
    const float cosX = glm::dot(x.shadingNormal, wi);
    const float cosFront = -glm::dot(y.normal, wi);   // > 0: x sees the front side
    const float cosY = y.twoSided ? std::abs(cosFront) : cosFront;
    if (cosX <= 0.0f || glm::dot(x.geometricNormal, wi) <= 0.0f || !(cosY > 0.0f)) {
        return glm::vec3(0.0f);
    }
    const float pdfLight = y.pdfArea * distance2 / cosY;
    if (!(pdfLight > 0.0f) || !std::isfinite(pdfLight)) return glm::vec3(0.0f);
    const glm::vec3 origin = offsetOrigin(x);
    const glm::vec3 target = y.position + std::copysign(y.offset, cosFront) * y.normal;
    const glm::vec3 span = target - origin;
    const float length = glm::length(span);
    if (!(length > 0.0f) ||
            occluded(origin, span / length, length * (1.0f - kShadowRayShortening), context,
                    counts)) {
        return glm::vec3(0.0f);
    }
    float weight = 1.0f;
    if (y.onGeometry) {
        weight = pdfLight / (pdfLight + bouncePdf(x, wi, cosX));
    }
    const glm::vec3 f = mGlossy ? glossyBrdf(x, wi) : x.albedo * glm::one_over_pi<float>();
    return f * y.radiance * (cosX / pdfLight * weight);
}

// MIS weight of emission a bounce ray (sampled with solid-angle density pdfBounce) found at
// `hit`: pB / (pB + pL) when the triangle is part of an area light (NEE at the bounce's origin
// could have picked the point), otherwise 1.
float PathTracer::bounceEmissionWeight(const Surface& hit, float pdfBounce, float distance2,
        const glm::vec3& direction) const {
    const float pdfArea = mAreaLights.pdfArea(hit.triangle);
    const float cosY = std::abs(glm::dot(hit.geometricNormal, direction));
    if (!(pdfArea > 0.0f) || !(cosY > 0.0f)) return 1.0f;
    const float pdfLight = pdfArea * distance2 / cosY;
    return std::isfinite(pdfLight) ? pdfBounce / (pdfBounce + pdfLight) : 0.0f;
}

// Samples one light vertex per point or spot light (the first light uses the stratified
// numbers u[0..1], the others `rng`).
void PathTracer::sampleLightVertices(const float u[2], Pcg32& rng,
        std::vector<LightVertex>& vertices, RTCIntersectContext& context,
        RayCounts& counts) const {
    vertices.resize(mLights.size());
    for (std::size_t i = 0; i < mLights.size(); ++i) {
        LightVertex& vertex = vertices[i];
        vertex.valid = false;
        const scene::Light& light = mLights[i];
        if (mEmissionPdf[i] <= 0.0f) continue;
        const float u1 = i == 0 ? u[0] : rng.nextFloat();
        const float u2 = i == 0 ? u[1] : rng.nextFloat();
        const glm::vec3 radiant = light.color * light.intensity;
        if (!usableLight(light, radiant)) continue;
        const glm::vec3 direction = lightSubpathDirection(light, u1, u2);
        RTCRayHit rayHit =
                ray(light.position, direction, std::numeric_limits<float>::infinity());
        ++counts.light;
        rtcIntersect1(mState.rtcScene, &context, &rayHit);
        if (!interact(rayHit, vertex.surface)) continue;
        const Surface& s = vertex.surface;
        glm::vec3 wi;
        float distance = 0.0f, factor = 0.0f;
        if (!reflects(s) || !lightGeometry(light, s.position, wi, distance, factor)) {
            continue;
        }
        const float cosTheta = glm::dot(s.shadingNormal, wi);
        if (cosTheta <= 0.0f) continue;
        vertex.radiance = radiant * (factor * cosTheta);
        if (!mGlossy) vertex.radiance = s.albedo * glm::one_over_pi<float>() * vertex.radiance;
        vertex.toLight = wi;
        vertex.pdfArea = mEmissionPdf[i] * std::abs(glm::dot(s.geometricNormal, wi)) /
                         (distance * distance);
        vertex.valid = vertex.pdfArea > 0.0f && std::isfinite(vertex.pdfArea);
    }
}

// Strategy (B): light reflected once at each light vertex y towards x, i.e.
// rho_x/pi cos_s(x) |cos_g(y)| / d^2 x L_y x V(x, y) / (pA + pB).
glm::vec3 PathTracer::connect(const Surface& x, const std::vector<LightVertex>& vertices,
        RTCIntersectContext& context, RayCounts& counts) const {
    glm::vec3 sum(0.0f);
    for (const LightVertex& vertex : vertices) {
        if (!vertex.valid) continue;
        const Surface& y = vertex.surface;
        const glm::vec3 toY = y.position - x.position;
        const float distance2 = glm::dot(toY, toY);
        if (!(distance2 > 0.0f)) continue;
        const glm::vec3 w = toY / std::sqrt(distance2);
        const float cosX = glm::dot(x.shadingNormal, w);
        const float cosY = -glm::dot(y.geometricNormal, w);
        if (cosX <= 0.0f || glm::dot(x.geometricNormal, w) <= 0.0f || cosY <= 0.0f) continue;
        const float geometry = cosX * cosY / distance2;
        const float pdfBsdf = mGlossy ? bouncePdf(x, w, cosX) * cosY / distance2
                                      : geometry * glm::one_over_pi<float>();
        if (!visible(x, y, context, counts)) continue;
        glm::vec3 radiance = vertex.radiance;
        if (mGlossy) {
            radiance *= glossyBrdf(x, w) *
                        evaluateBrdf(y.brdf, y.shadingNormal, -w, vertex.toLight);
        }
        sum += radiance * (geometry / (pdfBsdf + vertex.pdfArea));
    }
    return mGlossy ? sum : x.albedo * glm::one_over_pi<float>() * sum;
}

bool PathTracer::reflects(const Surface& surface) const {
    if (!mGlossy) return maxComponent(surface.albedo) > 0.0f;
    return maxComponent(surface.brdf.diffuse) > 0.0f || maxComponent(surface.brdf.f0) > 0.0f;
}

glm::vec3 PathTracer::glossyBrdf(const Surface& surface, const glm::vec3& wi) const {
    if (!mGlossy) return glm::vec3(1.0f);
    return evaluateBrdf(surface.brdf, surface.shadingNormal, surface.toViewer, wi);
}

float PathTracer::bouncePdf(const Surface& surface, const glm::vec3& wi, float cosWi) const {
    if (!mGlossy) return cosWi * glm::one_over_pi<float>();
    return brdfPdf(surface.brdf, surface.shadingNormal, surface.toViewer, wi);
}

// Whether the segment from x to y is free. A ray arriving at y at a grazing angle may touch
// y's own plane a little before y by rounding; hits within that plane count as arriving.
bool PathTracer::visible(const Surface& x, const Surface& y, RTCIntersectContext& context,
        RayCounts& counts) const {
    const glm::vec3 origin = offsetOrigin(x);
    const glm::vec3 span = y.position - origin;
    const float length = glm::length(span);
    if (!(length > 0.0f)) return false;
    const glm::vec3 direction = span / length;
    RTCRayHit rayHit = ray(origin, direction, length * (1.0f - kShadowRayShortening));
    ++counts.shadow;
    rtcIntersect1(mState.rtcScene, &context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return true;
    const glm::vec3 hit = origin + rayHit.ray.tfar * direction;
    return std::abs(glm::dot(hit - y.position, y.geometricNormal)) <= 4.0f * y.offset;
}

} // namespace gi::reference
