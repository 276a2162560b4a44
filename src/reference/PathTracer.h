// One path per call through the reference renderer's Embree scene: next-event estimation at
// every vertex, and light reaching bounce vertices from point and spot lights estimated by two
// strategies (bounce sampling and light subpaths) combined by multiple importance sampling.
#pragma once

#include "reference/EmbreeScene.h"
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
    glm::vec3 emission{0.0f};
    float offset = 0.0f;               // metres to move ray origins off the surface
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
    glm::vec3 radiance{0.0f};   // rho/pi x colour x intensity x E-factor x cos at the vertex
    float pdfArea = 0.0f;       // emissionPdf x |cos_g| / d^2
    bool valid = false;
};

// Everything one render() call shares between its worker threads.
//
// Light transport: a path x0 (camera hit), x1, ... of length up to `bounces` bounces. Direct
// light at x0 is next-event estimation (NEE). Light reaching x_j (j >= 1) from a point or spot
// light, i.e. the paths x_(j-1) -> x_j -> light, is estimated with two strategies combined by
// multiple importance sampling with the balance heuristic (Veach 1997, ch. 9; PBRT 3rd ed.
// 14.3 and 16.3): (A) x_j found by cosine sampling at x_(j-1), then NEE at x_j; (B) x_j found
// as the first hit of a ray sampled from the light's emission (a light vertex), then connected
// to x_(j-1) with a visibility ray. (A) alone is noisy where a light sits close to a surface
// (the Cornell box's light is 1 cm under the ceiling: a hot spot a bounce ray rarely finds);
// (B) handles that, while (A) handles nearby geometry, where (B)'s 1/d^2 diverges. Both
// weights use area densities at x_j: pA = cos_s(x_(j-1))/pi |cos_g(x_j)| / d^2 and
// pB = emissionPdf |cos_g(x_j, light)| / d_light^2; each strategy contributes f / (pA + pB).
class PathTracer {
public:
    PathTracer(const EmbreeState& state, const std::vector<scene::Light>& lights,
            const scene::CameraView& camera, int width, int height, int bounces);

    // One path through continuous image coordinates (x, y), x in [0, width) left to right,
    // y in [0, height) top to bottom. u[0..1]: the first bounce direction, u[2..3]: the first
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
    void sampleLightVertices(const float u[2], Pcg32& rng, std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const;
    glm::vec3 connect(const Surface& x, const std::vector<LightVertex>& vertices,
            RTCIntersectContext& context, RayCounts& counts) const;
    bool visible(const Surface& x, const Surface& y, RTCIntersectContext& context,
            RayCounts& counts) const;

    const EmbreeState& mState;
    const std::vector<scene::Light>& mLights;
    std::vector<float> mEmissionPdf;   // per light, emissionPdf()
    int mWidth, mHeight, mBounces;
    // Clip-to-world images of (ndcX, ndcY, -1 | +1, 1) = [0] + ndcX [1] + ndcY [2], homogeneous.
    glm::dvec4 mNear[3];
    glm::dvec4 mFar[3];
};

} // namespace gi::reference
