#include "gi/voxel/ConeSet.h"

#include <glm/glm.hpp>

#include <cmath>

namespace gi::voxel {
namespace {

// Every cone an equal share 1/N of the cosine-weighted hemisphere: the share below elevation
// theta is sin^2 theta, so the central cone takes sin^2 theta < 1/N and each ring the next
// band of `count` shares, its cones at the band's middle in sin^2 theta.
ConeSet equalShares(int first, int second) {
    const int total = 1 + first + second;
    const float share = 1.0f / float(total);
    ConeSet set;
    set.centralWeight = share;
    int below = 1;
    for (int k = 0; k < 2; ++k) {
        const int count = k == 0 ? first : second;
        const float middle = (float(below) + 0.5f * float(count)) * share;
        set.rings[std::size_t(k)] = {count, std::asin(std::sqrt(middle)), share};
        below += count;
    }
    // A cap of 1/N of the hemisphere's solid angle: 2 pi (1 - cos a) = 2 pi / N.
    set.apertureDegrees = 2.0f * glm::degrees(std::acos(1.0f - share));
    return set;
}

// The thesis' 9: the ring at 50 degrees, the central cap up to halfway to it.
ConeSet thesisCones() {
    const float ring = glm::radians(50.0f);
    const float boundary = std::sin(0.5f * ring);
    ConeSet set;
    set.centralWeight = boundary * boundary;
    set.rings[0] = {8, ring, (1.0f - set.centralWeight) / 8.0f};
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
    ConeSet set = cones == VOXEL_CONES_THESIS ? thesisCones() : equalShares(6, 12);
    if (apertureDegrees > 0.0f) set.apertureDegrees = apertureDegrees;
    return set;
}

} // namespace gi::voxel
