// One path per call through the reference renderer's Embree scene: next-event estimation of
// every light at every vertex, combined by multiple importance sampling with the bounce rays
// (area lights) and with light subpaths (point and spot lights); see PathTracer below.
#pragma once

#include "reference/AreaLightSampling.h"
#include "reference/EmbreeScene.h"
#include "reference/GltfBrdf.h"
#include "reference/Pcg32.h"
#include "reference/ReferenceRenderer.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <vector>

namespace gi::reference {

struct Surface {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};   // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};     // unit, on the side the ray came from
    glm::vec3 albedo{0.0f};
    glm::vec3 toViewer{0.0f};          // unit, towards the ray's origin
    GltfBrdf brdf;                     // the glossy model's BRDF (unused when Lambertian)
    glm::vec3 emission{0.0f};          // towards the ray's origin (0 from a back side)
    float offset = 0.0f;               // metres to move ray origins off the surface
    std::uint32_t triangle = 0;        // index into EmbreeState::triangles
};

struct PathSample {
    glm::vec3 direct{0.0f};
    glm::vec3 indirect{0.0f};
    bool hit = false;
};

// The first surface a light's emission hits (a light subpath of one vertex), with what the
// connection strategy needs: its outgoing radiance due to the light and its area density.
struct LightVertex {
    Surface surface;
    glm::vec3 radiance{0.0f};   // rho/pi x colour x intensity x E-factor x cos at the vertex;
                                // glossy model: without rho/pi (f depends on where it goes)
    glm::vec3 toLight{0.0f};    // unit, from the vertex towards the light
    float pdfArea = 0.0f;       // emissionPdf x |cos_g| / d^2
    bool valid = false;
};

// Everything one render() call shares between its worker threads.
//
// Light transport: a path x0 (camera hit), x1, ... of up to `bounces` bounces, each bounce
// direction cosine-sampled (pdf cos_s/pi). At every vertex x_0 .. x_k (k = bounces) the light
// scattered there once more is estimated: at x0 this is the `direct` term (with the emission
// the camera sees), at later vertices `indirect`. So every kind of light reaches the image
// after at most k + 1 scatterings (bounces = 0: direct light only). Per kind of light:
// - Point, spot, directional: next-event estimation (NEE). Light reaching x_j (j >= 1) from a
//   point or spot light, i.e. the paths x_(j-1) -> x_j -> light, is estimated with two
//   strategies combined by multiple importance sampling with the balance heuristic (Veach
//   1997, ch. 9; PBRT 3rd ed. 14.3 and 16.3): (A) x_j found by cosine sampling at x_(j-1), then
//   NEE at x_j; (B) x_j found as the first hit of a ray sampled from the light's emission (a
//   light vertex), then connected to x_(j-1) with a visibility ray. (A) alone is noisy where
//   a light sits close to a surface (the Cornell box's light is 1 cm under the ceiling: a hot
//   spot a bounce ray rarely finds); (B) handles that, while (A) handles nearby geometry, where
//   (B)'s 1/d^2 diverges. Both weights use area densities at x_j: pA = cos_s(x_(j-1))/pi
//   |cos_g(x_j)| / d^2 and pB = emissionPdf |cos_g(x_j, light)| / d_light^2; each strategy
//   contributes f / (pA + pB).
// - Emissive surfaces and area lights: the cosine ray from x_j finds emission by hitting it;
//   its emission belongs to x_j's term (emission the ray from x0 finds is direct light). In
//   scenes with emissive surfaces (or a sky) the last vertex x_k casts this ray too, as a
//   closing ray that only collects emission and sky. Area lights are also sampled by NEE: one
//   point of all area lights' triangles (AreaLightSampling.h) and a visibility ray. For a
//   point on scene geometry both estimates are weighted by the balance heuristic over
//   solid-angle densities at x_j, pL = pArea d^2 / |cos_y| and pB = cos_s(x_j)/pi; emitters
//   that are not geometry (command-line rectangles) are NEE only (weight 1), emissive
//   triangles of no area light are found by hits only (weight 1). Emission leaves the front
//   side only, both sides when the material is double-sided, for NEE and hits alike.
// - Sky (constant radiance L from every direction no geometry blocks): the cosine ray of x_j,
//   when it escapes, adds rho L to x_j's term; it samples the sky with the sky's own ideal
//   density for a Lambertian surface, so no other strategy or weight is needed. An open plane
//   thus shows rho L exactly (E = pi L), also with bounces = 0 (the closing ray). Camera rays
//   that escape stay black: the sky lights the scene but is not drawn as a background.
// Glossy model (`glossy`, GltfBrdf.h): every surface has the glTF metallic-roughness BRDF f
// instead of rho/pi, bounce directions come from sampleBrdf() (a random lobe choice drawn from
// `rng`) with the throughput multiplied by f cos / pdf, and every MIS weight above uses
// brdfPdf() where it used cos/pi. Lambertian scenes keep their arithmetic and random streams.
class PathTracer {
public:
    PathTracer(const EmbreeState& state, const std::vector<scene::Light>& lights,
            const scene::CameraView& camera, int width, int height, int bounces,
            bool glossy = false);

    // One path through continuous image coordinates (x, y), x in [0, width) left to right,
    // y in [0, height) top to bottom. u[0..1]: the camera hit's cosine ray, u[2..3]: the first
    // light's emission direction; everything else comes from `rng`. `lightVertices` is scratch
    // space reused between calls.
    PathSample trace(float x, float y, const float u[4], Pcg32& rng,
            std::vector<LightVertex>& lightVertices, RayCounts& counts) const;

private:
    static RTCRayHit ray(const glm::vec3& origin, const glm::vec3& direction, float tfar);
    // The ray through a point of the image, from the near plane to the far plane, exactly as
    // the raster passes clip it.
    RTCRayHit cameraRay(float x, float y) const;
    static glm::vec3 offsetOrigin(const Surface& surface);
    bool interact(const RTCRayHit& rayHit, Surface& surface) const;
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tfar,
            RTCIntersectContext& context, RayCounts& counts) const;
    glm::vec3 directLight(const Surface& surface, float pdfArea, RTCIntersectContext& context,
            RayCounts& counts) const;
    glm::vec3 areaLight(const Surface& x, float u1, float u2, RTCIntersectContext& context,
            RayCounts& counts) const;
    float bounceEmissionWeight(const Surface& hit, float pdfBounce, float distance2,
            const glm::vec3& direction) const;
    bool reflects(const Surface& surface) const;
    // f(toViewer, wi) of the glossy model; 1 for Lambertian surfaces, whose rho/pi the callers
    // apply once to their sums.
    glm::vec3 glossyBrdf(const Surface& surface, const glm::vec3& wi) const;
    // Solid-angle density of the bounce sampling at `surface` towards wi.
    float bouncePdf(const Surface& surface, const glm::vec3& wi, float cosWi) const;
    void sampleLightVertices(const float u[2], Pcg32& rng, std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const;
    glm::vec3 connect(const Surface& x, const std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const;
    bool visible(const Surface& x, const Surface& y, RTCIntersectContext& context,
            RayCounts& counts) const;

    const EmbreeState& mState;
    const std::vector<scene::Light>& mLights;
    std::vector<float> mEmissionPdf;   // per light, emissionPdf()
    AreaLightSampler mAreaLights;
    glm::vec3 mSky{0.0f};              // radiance of all sky lights together
    bool mClosingRay = false;          // the last vertex casts a cosine ray too (see above)
    int mWidth, mHeight, mBounces;
    bool mGlossy;
    // Clip-to-world images of (ndcX, ndcY, -1 | +1, 1) = [0] + ndcX [1] + ndcY [2], homogeneous.
    glm::dvec4 mNear[3];
    glm::dvec4 mFar[3];
};

} // namespace gi::reference
