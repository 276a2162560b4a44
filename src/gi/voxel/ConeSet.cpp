#include "gi/voxel/ConeSet.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace gi::voxel {
namespace {

// Every cone an equal share 1/N of the cosine-weighted hemisphere: the share below elevation
// theta is sin^2 theta, so the central cone takes sin^2 theta < 1/N and each ring the next
// band of `count` shares, its cones at the band's middle in sin^2 theta.
ConeSet equalShares(std::initializer_list<int> counts) {
    int total = 1;
    for (const int count : counts) total += count;
    const float share = 1.0f / float(total);
    ConeSet set;
    set.centralWeight = share;
    // A cap of 1/N of the hemisphere's solid angle: 2 pi (1 - cos a) = 2 pi / N.
    set.apertureDegrees = 2.0f * glm::degrees(std::acos(1.0f - share));
    int below = 1;
    std::size_t k = 0;
    for (const int count : counts) {
        const float middle = (float(below) + 0.5f * float(count)) * share;
        set.rings[k++] = {count, std::asin(std::sqrt(middle)), share, float(below) * share,
                          float(below + count) * share};
        below += count;
    }
    return set;
}

// The thesis' 9: the ring at 50 degrees, the central cap up to halfway to it.
ConeSet thesisCones() {
    const float ring = glm::radians(50.0f);
    const float boundary = std::sin(0.5f * ring);
    ConeSet set;
    set.centralWeight = boundary * boundary;
    set.rings[0] = {8, ring, (1.0f - set.centralWeight) / 8.0f, set.centralWeight, 1.0f};
    set.apertureDegrees = 45.0f;
    return set;
}

} // namespace

int ConeSet::conesPerPixel(int classes) const {
    int cones = 1;
    for (const ConeRing& ring : rings) cones += (ring.count + classes - 1) / classes;
    return cones;
}

float ConeSet::totalWeight() const {
    float total = centralWeight;
    for (const ConeRing& ring : rings) total += float(ring.count) * ring.weight;
    return total;
}

ConeSet coneSet(int cones, float apertureDegrees) {
    ConeSet set = cones == VOXEL_CONES_THESIS ? thesisCones()
                : cones == VOXEL_CONES_DENSE  ? equalShares({6, 12, 18})
                                              : equalShares({6, 12});
    if (apertureDegrees > 0.0f) set.apertureDegrees = apertureDegrees;
    // A cone whose axis is at most 90 degrees less its half-aperture from the normal keeps its
    // rim above the surface: sin^2 of that angle is cos^2 of the half-aperture.
    const float halfAperture = glm::radians(0.5f * set.apertureDegrees);
    const float rim = std::cos(halfAperture) * std::cos(halfAperture);
    for (ConeRing& ring : set.rings) {
        if (ring.count == 0) continue;
        const float middle = std::sin(ring.elevation) * std::sin(ring.elevation);
        ring.riseReach = std::max(
                std::min({middle - ring.bandLow, ring.bandHigh - middle, rim - middle}), 0.0f);
    }
    return set;
}

} // namespace gi::voxel
